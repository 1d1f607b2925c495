// fuzz_recording_csv.cc: libFuzzer harness for the recording reader (read_recording_csv, what
// `pamsim identify` reads a lab's recordings with): any bytes as a CSV file are read into a
// recording or refused with an InputError.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.h"
#include "base/input_error.h"
#include "sim/io/recording_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    pamsim::read_recording_csv(pamsim_fuzz::input_file(data, size, ".csv"));
  } catch (const pamsim::InputError&) {
  }
  return 0;
}
