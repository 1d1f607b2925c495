// hil_budget.h: the hardware-in-the-loop packets (src/embedded/pamhil.h) against a serial
// line's rate: bytes per control tick each way for a number of muscles and an encoding, and
// the share of an 8N1 line (10 bits a byte) they take at a control rate.
#pragma once

#include <string>

namespace pamsim {

struct HilBudget {
  int readings_bytes = 0;  // pamsim -> board, per tick
  int command_bytes = 0;   // board -> pamsim, per tick
  double line_share = 0;   // the larger direction's bytes per second over the line's
};

HilBudget hil_budget(int muscles, int encoding, double control_hz, int baud);

// The table `pamsim hil --byte-budget` prints: 2 and 8 muscles, every encoding, at 100 Hz
// on 115 200 baud.
std::string hil_byte_budget_table();

}  // namespace pamsim
