// hil_budget.cc: see hil_budget.h.
#include "sim/hil/hil_budget.h"

#include <algorithm>
#include <cstdio>

#include "embedded/pamhil.h"

namespace pamsim {

HilBudget hil_budget(int muscles, int encoding, double control_hz, int baud) {
  HilBudget b;
  b.readings_bytes = pamhil_packet_bytes(PAMHIL_READINGS, encoding, muscles);
  b.command_bytes = pamhil_packet_bytes(PAMHIL_COMMAND, encoding, muscles);
  const double line_bytes_per_s = baud / 10.0;  // 8N1: a start, 8 data and a stop bit
  b.line_share = std::max(b.readings_bytes, b.command_bytes) * control_hz / line_bytes_per_s;
  return b;
}

std::string hil_byte_budget_table() {
  constexpr double kHz = 100.0;
  constexpr int kBaud = 115200;
  std::string text =
      "bytes per control tick at 100 Hz against 115200 baud 8N1 (11520 bytes/s each way)\n"
      "muscles  encoding  readings  command  line used  fits with 20 % margin\n";
  const char* names[] = {"float64", "float32", "counts"};
  for (int muscles : {2, 8}) {
    for (int encoding = PAMHIL_FLOAT64; encoding <= PAMHIL_COUNTS; ++encoding) {
      const HilBudget b = hil_budget(muscles, encoding, kHz, kBaud);
      char row[160];
      std::snprintf(row, sizeof(row), "%7d  %-8s  %8d  %7d  %8.0f %%  %s\n", muscles,
                    names[encoding], b.readings_bytes, b.command_bytes, 100.0 * b.line_share,
                    b.line_share <= 0.8 ? "yes" : "no");
      text += row;
    }
  }
  return text;
}

}  // namespace pamsim
