// fuzz_scenario.cc: libFuzzer harness for the scenario reader (load_scenario_text): any text
// read as a scenario beside the shipped ones (so relative model paths resolve) loads or is
// refused with an InputError.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "base/input_error.h"
#include "sim/scenario/scenario_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    pamsim::load_scenario_text(pamsim_fuzz::input_text(data, size),
                               PAMSIM_SOURCE_DIR "/scenarios/fuzz_input.toml");
  } catch (const pamsim::InputError&) {
  }
  return 0;
}
