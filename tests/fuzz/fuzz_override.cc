// fuzz_override.cc: libFuzzer harness for `--set key=value` (ConfigReader::apply_override),
// on an empty document and on the drop-mass scenario, where the value must also pass the
// scenario's checks or be refused with an InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_input.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/config_reader.h"
#include "sim/scenario/scenario_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string kDropMass = PAMSIM_SOURCE_DIR "/scenarios/drop_mass.toml";
  static const std::string kDropMassText = pamsim::read_text_file(kDropMass);
  const std::string assignment = pamsim_fuzz::input_text(data, size);
  try {
    pamsim::ConfigReader empty("", "fuzz");
    empty.apply_override(assignment);
  } catch (const pamsim::InputError&) {
  }
  try {
    pamsim::load_scenario_text(kDropMassText, kDropMass, {assignment});
  } catch (const pamsim::InputError&) {
  }
  return 0;
}
