// pressure_hardware.cc: see pressure_hardware.h.
#include "sensing/pressure_hardware.h"

#include <cmath>
#include <utility>

#include "base/units.h"
#include "sensing/checks.h"

namespace pamsim {
namespace {

using namespace checks;

// a pressure key in MPa, checked on its value in MPa
void require_mpa(const char* key, double pa, bool any_sign) {
  const double mpa = units::pa_to_mpa(pa);
  if (any_sign) {
    require_finite(key, mpa);
  } else {
    require_non_negative(key, mpa);
  }
}

}  // namespace

void validate(const PressureHardwareConfig& c) {
  require_mpa("sensors.pressure.bias_mean_MPa", c.bias_mean_pa, true);
  require_mpa("sensors.pressure.bias_stddev_MPa", c.bias_stddev_pa, false);
  if (!(c.gain_error_stddev_pct >= 0.0 && c.gain_error_stddev_pct <= 50.0)) {
    fail("sensors.pressure.gain_error_stddev_pct", "within [0, 50] %", c.gain_error_stddev_pct);
  }
  require_mpa("sensors.pressure.dynamic_bias_stddev_MPa", c.dynamic_bias_stddev_pa, false);
  require_positive("sensors.pressure.dynamic_bias_correlation_time_s",
                   c.dynamic_bias_correlation_time_s);
  require_mpa("sensors.pressure.hysteresis_MPa", c.hysteresis_pa, false);
  require_non_negative("sensors.pressure.response_time_ms", 1e3 * c.response_time_s);
  require_mpa("sensors.pressure.precision_MPa", c.precision_pa, false);
}

double response_cutoff_hz(double rise_time_s) {
  if (rise_time_s == 0.0) return 0.0;
  return std::log(10.0) / (2.0 * units::kPi * rise_time_s);
}

PressureHardware::PressureHardware(const PressureHardwareConfig& config,
                                   std::mt19937_64& instrument_rng, std::mt19937_64 trial_rng,
                                   double sample_period_s)
    : response_(response_cutoff_hz(config.response_time_s), sample_period_s),
      half_width_pa_(0.5 * config.hysteresis_pa),
      bias_pa_(config.bias_mean_pa + config.bias_stddev_pa * standard_normal(instrument_rng)),
      gain_error_(config.gain_error_stddev_pct / 100.0 * standard_normal(instrument_rng)),
      trial_rng_(std::move(trial_rng)),
      dynamic_bias_(config.dynamic_bias_stddev_pa, config.dynamic_bias_correlation_time_s,
                    sample_period_s, trial_rng_),
      precision_pa_(config.precision_pa) {
  if (half_width_pa_ > 0.0) {
    play_.count = 1;
    play_.weight[0] = 1.0;
    play_.breakaway_m[0] = half_width_pa_;   // a travel in pascals here
  }
}

double PressureHardware::sensed_pa(double p_pa) {
  // the element's first-order response to the chamber
  const double felt = response_.step(p_pa);
  // the play: the reading trails the input by up to half the loop's width
  if (!std::isnan(last_felt_pa_)) {
    maxwell_slip_advance(play_, felt - last_felt_pa_, &play_state_);
  }
  last_felt_pa_ = felt;
  const double played =
      felt - maxwell_slip_force(play_, &play_state_, half_width_pa_, half_width_pa_);
  // this instrument's zero and span, and its zero's drift
  return played * (1.0 + gain_error_) + bias_pa_ + dynamic_bias_.step(trial_rng_);
}

}  // namespace pamsim
