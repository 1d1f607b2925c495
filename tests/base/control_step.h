// control_step.h: the control tick the reflex and sensing tests step at, the period of the
// default sim.control_hz (100 Hz).
#pragma once

namespace pamsim_test {

inline constexpr double kControlDt = 0.01;  // [s]

}  // namespace pamsim_test
