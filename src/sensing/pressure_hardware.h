// pressure_hardware.h: the pressure sensor as hardware (sensors.pressure.model = "pse540")
// instead of an exact transducer with white noise: the static and dynamic errors of the SMC
// PSE540 class (0-1 MPa gauge, 1-5 V out; Yoshida and Hosoda, Sec. III-A, name the PSE540),
// in Gazebo's noise parameters (sensor_noise.h): response, hysteresis, the instrument's static
// error and a drifting zero (PressureHardware), with its figures in PressureHardwareConfig.
#pragma once

#include <limits>
#include <random>

#include "pam_actuator/maxwell_slip.h"
#include "sensing/lowpass_filter.h"
#include "sensing/sensor_noise.h"

namespace pamsim {

// Figures (the PSE540 datasheet itself could not be retrieved; these are the class figures
// sensors.h quotes for it, and assumptions where stated, each a row of docs/physics.md's
// departures):
//  - accuracy +-2 % F.S. (+-20 kPa): read as a 3-sigma bound on an instrument's static error
//    at full scale, shared equally by zero and span: bias_stddev = 2 % / (3 sqrt 2) F.S.
//    ~ 4.7 kPa, gain_error_stddev ~ 0.47 % (ASSUMPTION: the split and the 3 sigma);
//  - repeatability +-0.2 % F.S.: already the white noise (sensors.pressure_noise_MPa, 1 kPa);
//  - hysteresis: no separate class figure found; ASSUMED the repeatability's 0.2 % F.S.
//    (2 kPa loop width), the smallest static error the class specifies;
//  - response time: ASSUMED 1 ms (the piezoresistive class; far below the 10 ms control
//    tick, so it barely acts at 100 Hz);
//  - dynamic bias: ASSUMED 0.4 kPa stationary SD with a 3600 s correlation time: a zero
//    drift of 0.04 % F.S. per K (the class's +-2 % F.S. thermal figure over 0-50 C) in a lab
//    whose air wanders 1 K over the hour (Gazebo documents ~3600 s as typical);
//  - precision: 0 (the PSE540's output is analog; the ADC quantises).
// The arm's sensors are not the tensile rig's: the estimator's spring model was fitted on the
// rig, so this instrument's offset moves the estimated length (~66 mm/MPa: 4.7 kPa ~ 0.3 mm).
//
// Keys sensors.pressure.* (read in sim/io; SI inside, MPa / % / ms / s in the keys).
struct PressureHardwareConfig {
  bool enabled = false;                   // sensors.pressure.model: "ideal" | "pse540"
  double bias_mean_pa = 0.0;              // sensors.pressure.bias_mean_MPa, finite
  double bias_stddev_pa = 4700.0;         // sensors.pressure.bias_stddev_MPa, >= 0
  double gain_error_stddev_pct = 0.47;    // sensors.pressure.gain_error_stddev_pct, [0, 50]
  double dynamic_bias_stddev_pa = 400.0;  // sensors.pressure.dynamic_bias_stddev_MPa, >= 0
  double dynamic_bias_correlation_time_s = 3600.0;  // ..._correlation_time_s, > 0
  double hysteresis_pa = 2000.0;                    // sensors.pressure.hysteresis_MPa, >= 0
  double response_time_s = 1e-3;                    // sensors.pressure.response_time_ms, >= 0
  double precision_pa = 0.0;  // sensors.pressure.precision_MPa, >= 0 (0: none)
};

// Throws InputError "<key> must be ..., got <value>" naming the sensors.pressure.* key.
void validate(const PressureHardwareConfig& config);

// Per tick, in order:
//   1. response: the sensing element lags the chamber, a first order with the catalogue's
//      response time read as its 0-90 % rise, tau = t_r / ln 10 (lowpass_filter.h; the
//      chamber pressure held over the control tick, so exact for that input);
//   2. hysteresis: a play (backlash) operator of full width h: rising and falling readings
//      of one pressure differ by h (one Maxwell-slip element whose breakaway travel and
//      slip force are both h / 2, so its force is its deflection, the play;
//      pam_actuator/maxwell_slip.h);
//   3. static error of this instrument, drawn once from sensors.instrument_seed:
//      p (1 + g) + b, b ~ N(bias_mean, bias_stddev^2), g ~ N(0, gain_error_stddev^2);
//   4. dynamic bias: a Gauss-Markov drift of the zero (sensor_noise.h), drawn from the
//      trial's seed (a trial is the lab on another day);
// then the sensor's existing bias and white noise (sensors.pressure_bias_MPa,
// pressure_noise_MPa, in sensors.h), then `precision` (Gazebo's rounding of the output),
// then the 1-5 V transfer and the ADC.
class PressureHardware {
 public:
  // One built sensor: its bias and gain drawn from `instrument_rng` (two draws); its dynamic
  // bias from `trial_rng`, which it keeps drawing from (one draw per tick). sample_period_s > 0.
  PressureHardware(const PressureHardwareConfig& config, std::mt19937_64& instrument_rng,
                   std::mt19937_64 trial_rng, double sample_period_s);

  // Steps 1-4 above: the pressure this sensor senses at the end of a tick over which the
  // chamber held p_pa [Pa].
  double sensed_pa(double p_pa);
  // The output rounded to the precision (after the white noise).
  double rounded_pa(double p_pa) const { return quantise(p_pa, precision_pa_); }

  double bias_pa() const { return bias_pa_; }
  double gain_error() const { return gain_error_; }

 private:
  LowpassFilter response_;
  MaxwellSlipParams play_;  // one element, breakaway h / 2 (none for h = 0)
  double play_state_ = 0.0;
  double half_width_pa_ = 0.0;  // h / 2, the element's slip force
  double last_felt_pa_ = std::numeric_limits<double>::quiet_NaN();
  double bias_pa_ = 0.0;
  double gain_error_ = 0.0;
  std::mt19937_64 trial_rng_;
  GaussMarkov dynamic_bias_;
  double precision_pa_ = 0.0;
};

// The first-order cutoff whose 0-90 % rise time is t_r: f_c = ln 10 / (2 pi t_r); 0 for t_r = 0.
double response_cutoff_hz(double rise_time_s);

}  // namespace pamsim
