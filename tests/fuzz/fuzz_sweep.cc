// fuzz_sweep.cc: libFuzzer harness for the sweep file reader (load_sweep): any text as a
// sweep file beside the shipped scenarios loads (every point validated) or is refused with an
// InputError.
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_input.h"
#include "base/input_error.h"
#include "sim/sweep/sweep.h"

namespace {

// The trials a sweep document asks for (points x seeds, at least the axes' levels), as a
// double so it cannot wrap. Validating a sweep costs a scenario load per point (10^4 points
// take seconds under ASan, 10^6 minutes, as they should); inputs over kMaxTrials are skipped
// so that a slow but correct validation is not reported as a hang. The size checks
// themselves are tested in sweep_test and cli_sweep_test.
constexpr double kMaxTrials = 1000;

double integer_or(const toml::node* n, double fallback) {
  const auto* i = n ? n->as_integer() : nullptr;
  return i ? std::fabs(static_cast<double>(i->get())) : fallback;
}

double trials_asked(const toml::table& doc) {
  double points = integer_or(doc.get("samples"), 1);
  if (const auto* axes = doc.get_as<toml::array>("axis")) {
    for (const auto& a : *axes) {
      const auto* t = a.as_table();
      if (!t) continue;
      const auto* values = t->get_as<toml::array>("values");
      points *= std::max(
          1.0, values ? static_cast<double>(values->size()) : integer_or(t->get("count"), 1));
    }
  }
  return points * std::max(1.0, integer_or(doc.get("seeds"), 1));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // the input as scenarios/sweep.toml of a mirror of the source tree
  static const pamsim_fuzz::RemovedAtExit root{pamsim_fuzz::source_mirror("sweep", "scenarios")};
  static const std::string path = root.path + "/scenarios/sweep.toml";
  try {
    if (trials_asked(toml::parse(pamsim_fuzz::input_text(data, size))) > kMaxTrials) return 0;
  } catch (const toml::parse_error&) {  // the reader must say so too
  }
  pamsim_fuzz::write_input(path, data, size);
  try {
    pamsim::load_sweep(path);
  } catch (const pamsim::InputError&) {
  }
  return 0;
}
