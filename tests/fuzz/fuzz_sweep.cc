// fuzz_sweep.cc: libFuzzer harness for the sweep file reader (load_sweep): any text as a
// sweep file beside the shipped scenarios loads (every point validated) or is refused with an
// InputError.
#include <toml++/toml.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "fuzz_input.h"
#include "pam_actuator/input_error.h"
#include "sim/sweep/sweep.h"

namespace {

// True if the document holds an integer above `limit` anywhere. Validating a sweep costs a
// scenario load per point (a 10^6-point grid takes minutes, as it should); such inputs are
// skipped so that a slow but correct validation is not reported as a hang. The size limits
// themselves are tested in sweep_test and cli_sweep_test.
bool has_large_integer(const toml::node& node, std::int64_t limit) {
  if (const auto* i = node.as_integer()) return i->get() > limit;
  if (const auto* t = node.as_table()) {
    for (const auto& [k, v] : *t) {
      if (has_large_integer(v, limit)) return true;
    }
  }
  if (const auto* a = node.as_array()) {
    if (static_cast<std::int64_t>(a->size()) > limit) return true;
    for (const auto& v : *a) {
      if (has_large_integer(v, limit)) return true;
    }
  }
  return false;
}

// A folder that looks like the source tree (scenarios/ with links to the shipped scenario
// files, models/ a link), where the input is written as scenarios/sweep.toml: its base
// "drop_mass.toml" and that scenario's "../models/..." resolve as in the source tree, and
// nothing is written there.
std::string sweep_path() {
  namespace fs = std::filesystem;
  const fs::path root =
      fs::temp_directory_path() / ("pamsim_fuzz_sweep_" + std::to_string(::getpid()));
  const fs::path source = PAMSIM_SOURCE_DIR;
  fs::remove_all(root);
  fs::create_directories(root / "scenarios");
  fs::create_directory_symlink(source / "models", root / "models");
  for (const auto& e : fs::directory_iterator(source / "scenarios")) {
    fs::create_symlink(e.path(), root / "scenarios" / e.path().filename());
  }
  return (root / "scenarios" / "sweep.toml").string();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string path = sweep_path();
  try {
    if (has_large_integer(toml::parse(pamsim_fuzz::input_text(data, size)), 100)) return 0;
  } catch (const toml::parse_error&) {  // the reader must say so too
  }
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    pamsim::load_sweep(path);
  } catch (const pamsim::InputError&) {
  }
  return 0;
}
