// fuzz_readings_csv.cc: libFuzzer harness for the readings reader (read_control_stream, what
// `pamsim controller replay` reads a readings.csv, a trajectory.csv or a lab's log with): any
// bytes as a log of two muscles are read into a stream, whose rate is then checked, or refused
// with an InputError.
#include <cstddef>
#include <cstdint>
#include <string>

#include "base/input_error.h"
#include "sim/io/controller_replay.h"
#include "sim/io/readings_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const pamsim::ControlStream stream =
        pamsim::read_control_stream(text, "fuzz.csv", {"ago", "anta"});
    pamsim::check_control_rate(stream, 0.01, "fuzz.csv");
  } catch (const pamsim::InputError&) {
  }
  return 0;
}
