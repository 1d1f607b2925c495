// fuzz_identify.cc: libFuzzer harness for the identification file reader
// (load_identify_definition): any text as an identification file beside the worked example
// (examples/identify: its arm.toml and recordings/ resolve) loads, every recording's scenario
// checked, or is refused with an InputError. The identification itself is not run.
#include <toml++/toml.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_input.h"
#include "base/input_error.h"
#include "sim/optimize/identify_file.h"

namespace {

// The scenario loads a file's validation costs: each recording's scenario at 1 + 2 x
// parameters settings. Inputs over kMaxLoads are skipped so that a slow but correct
// validation (tenths of a second per load under ASan) is not reported as a hang.
constexpr double kMaxLoads = 60;

double loads_asked(const toml::table& doc) {
  const auto count = [&](const char* key) {
    const auto* a = doc.get_as<toml::array>(key);
    return a ? static_cast<double>(a->size()) : 0.0;
  };
  return (1.0 + 2.0 * count("parameter")) * std::max(1.0, count("recording"));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // the input as examples/identify/id.toml of a mirror of the source tree
  static const pamsim_fuzz::RemovedAtExit root{
      pamsim_fuzz::source_mirror("identify", "examples/identify")};
  static const std::string path = root.path + "/examples/identify/id.toml";
  try {
    if (loads_asked(toml::parse(pamsim_fuzz::input_text(data, size))) > kMaxLoads) return 0;
  } catch (const toml::parse_error&) {  // the reader must say so too
  }
  pamsim_fuzz::write_input(path, data, size);
  try {
    pamsim::load_identify_definition(path);
  } catch (const pamsim::InputError&) {
  }
  return 0;
}
