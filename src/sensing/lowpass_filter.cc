// lowpass_filter.cc: first-order low-pass, exact zero-order-hold discretisation.
#include "sensing/lowpass_filter.h"

#include <cassert>
#include <cmath>

#include "base/units.h"

namespace pamsim {

double lowpass_alpha(double cutoff_hz, double sample_period_s) {
  assert(std::isfinite(cutoff_hz) && cutoff_hz >= 0.0);
  assert(std::isfinite(sample_period_s) && sample_period_s > 0.0);
  if (cutoff_hz == 0.0) return 1.0;
  return -std::expm1(-2.0 * units::kPi * cutoff_hz * sample_period_s);
}

LowpassFilter::LowpassFilter(double cutoff_hz, double sample_period_s) {
  pamctl_lowpass_init(&filter_, lowpass_alpha(cutoff_hz, sample_period_s));
}

double LowpassFilter::step(double x) { return pamctl_lowpass_step(&filter_, x); }

}  // namespace pamsim
