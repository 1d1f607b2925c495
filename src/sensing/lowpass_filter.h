// lowpass_filter.h: the first-order low-pass used on measured pressure and on velocity
// (the paper's suggested fix for noisy velocity, Sec. V-C), discretised exactly for the
// control period. The update is the embedded controller's (pamctl_lowpass_step,
// src/embedded/pamctl.h).
#pragma once

#include "embedded/pamctl.h"

namespace pamsim {

// Continuous filter: tau dy/dt = x - y, tau = 1 / (2 pi fc). Holding x constant over one
// sample period dt (zero-order hold) the exact update is
//   y_j = y_{j-1} + alpha (x_j - y_{j-1}),   alpha = 1 - exp(-2 pi fc dt),
// so a unit step applied at sample 0 reads y_n = 1 - exp(-n dt / tau) at sample n, and the
// DC gain is exactly 1. First order rather than Butterworth: one state, no overshoot (a
// 2nd-order Butterworth rings by 4 %, which a threshold detector would see as velocity),
// and a prototype's figures for it (5 Hz on pressure, 10 Hz on velocity: sensing.h,
// sensors.h) were measured with it.
//
// The filter is initialised to its first input (no start-up transient). A cutoff of 0
// turns it off: the output is the input.
class LowpassFilter {
 public:
  // cutoff_hz >= 0 (0 = off), sample_period_s > 0; both finite. Violations are internal
  // errors (the scenario keys are checked by validate() in sensing.h): asserted.
  LowpassFilter(double cutoff_hz, double sample_period_s);

  // One sample in, one sample out. The first call returns its input.
  double step(double x);

  // Forget the state: the next step() initialises again.
  void reset() { filter_.started = false; }

  double alpha() const { return filter_.alpha; }  // 1 when off
  double output() const { return filter_.y; }

 private:
  pamctl_lowpass filter_{};
};

// alpha = 1 - exp(-2 pi fc dt); 1 for fc = 0 (pass-through).
double lowpass_alpha(double cutoff_hz, double sample_period_s);

}  // namespace pamsim
