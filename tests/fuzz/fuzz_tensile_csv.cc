// fuzz_tensile_csv.cc: libFuzzer harness for the tensile CSV reader (read_tensile_csv):
// any bytes as a CSV file are read into rows or refused with an InputError.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "base/input_error.h"
#include "pam_actuator/tensile_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    pamsim::read_tensile_csv(pamsim_fuzz::input_file(data, size, ".csv"));
  } catch (const pamsim::InputError&) {
  }
  return 0;
}
