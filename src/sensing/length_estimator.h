// length_estimator.h: model-based length and velocity of one PAM from its pressure sensor
// and strain gauge alone (paper Sec. II, III-C/D; Eq. (1)-(5), (9)-(11), per tick at
// LengthEstimator), the estimate the stretch reflex runs on. The arithmetic is the embedded
// controller's (pamctl_estimate_length, src/embedded/pamctl.h), which the robot runs.
#pragma once

#include "pam_actuator/pam_params.h"
#include "pam_actuator/spring_model.h"
#include "embedded/pamctl.h"
#include "sensing/lowpass_filter.h"

namespace pamsim {

// A muscle's estimator law and gauge as the embedded controller holds them; the pressure
// sensor's line and the sensors' ranges are left 0 for the caller (SensorSuite) to fill.
pamctl_muscle_config embedded_muscle(const SpringModel& spring, const StrainGaugeParams& gauge);

struct LengthEstimatorParams {
  double pressure_lowpass_hz = 0.0;  // sensors.pressure_lowpass_hz [Hz], 0 = off
  double velocity_lowpass_hz = 0.0;  // reflex.lowpass_hz [Hz], 0 = off
};

struct LengthEstimate {
  double pressure_pa = 0.0;  // pressure used in the inversion (filtered if configured)
  double force_n = 0.0;      // Eq. (9), may be negative with noise (then slack)
  double d_m = 0.0;          // deformation, >= 0
  InversionStatus status = InversionStatus::kSlack;
  double length_m = 0.0;      // Eq. (1)
  double velocity_m_s = 0.0;  // Eq. (11), filtered if configured
};

// Per control tick j, with SI units inside (p [Pa] gauge, f [N], d and l [m]):
//   p      = lowpass(p_meas)                   optional, cutoff pressure_lowpass_hz (0 = off)
//   f      = (V - V_base) / q                  Eq. (9), q [V/N], V and V_base [V]
//   d      = invert_spring_model(p, f)         Eq. (3)-(5) solved for d, Eq. (10)
//   l      = l_n(p) + d = m p + h + d          Eq. (1)-(2)
//   v_j    = (l_j - l_{j-1}) / dt              Eq. (11), 0 at the first tick
//   v      = lowpass(v_j)                      optional, cutoff velocity_lowpass_hz (0 = off)
// A slack line (f <= 0) gives d = 0, l = l_n(p): the paper's Fig. 7 behaviour (the gauge
// cannot see compression). A force beyond what the law can produce at p (no physical root)
// holds the last valid d (0 before any) instead of jumping to d = 0, which would read as a
// large false velocity; the status reports it.
// Low-pass filters are first order, exact for dt (lowpass_filter.h), initialised to the
// first sample.
class LengthEstimator {
 public:
  // sample_period_s > 0 (dt of Eq. (11)); cutoffs >= 0. Asserted: validate() in
  // sensing.h checks the scenario keys before anything is built.
  LengthEstimator(const SpringModel& spring, const StrainGaugeParams& gauge,
                  const LengthEstimatorParams& params, double sample_period_s);

  // One tick from the measured pressure [Pa] and the gauge voltage [V].
  LengthEstimate update(double pressure_meas_pa, double gauge_v);

 private:
  pamctl_muscle_config muscle_;
  double dt_s_;
  pamctl_muscle_state state_{};
};

}  // namespace pamsim
