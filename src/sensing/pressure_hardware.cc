// pressure_hardware.cc: see pressure_hardware.h.
#include "sensing/pressure_hardware.h"

#include <cmath>
#include <utility>

#include "base/units.h"
#include "sensing/instrument_keys.h"

namespace pamsim {

void validate(const PressureHardwareConfig& c) {
  PressureHardwareConfig fields = c;  // each key's own range (instrument_keys.h)
  check_key_rows(pressure_hardware_key_table(&fields));
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
    play_.breakaway_m[0] = half_width_pa_;  // a travel in pascals here
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
