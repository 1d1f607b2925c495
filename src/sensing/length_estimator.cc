// length_estimator.cc: Eq. (9)-(11) on measured pressure and gauge voltage.
#include "sensing/length_estimator.h"

#include <cassert>

namespace pamsim {

LengthEstimator::LengthEstimator(const SpringModel& spring, const StrainGaugeParams& gauge,
                                 const LengthEstimatorParams& params, double sample_period_s)
    : spring_(spring),
      gauge_(gauge),
      dt_s_(sample_period_s),
      pressure_filter_(params.pressure_lowpass_hz, sample_period_s),
      velocity_filter_(params.velocity_lowpass_hz, sample_period_s) {
  assert(gauge.q_v_per_n > 0.0);
}

LengthEstimate LengthEstimator::update(double pressure_meas_pa, double gauge_v) {
  LengthEstimate est;
  // pressure, optionally low-passed, and force from the gauge, Eq. (9)
  est.pressure_pa = pressure_filter_.step(pressure_meas_pa);
  est.force_n = (gauge_v - gauge_.v_base_v) / gauge_.q_v_per_n;

  // deformation by inverting the spring law, Eq. (10); slack gives d = 0
  const DeformationEstimate inv = invert_spring_model(spring_, est.pressure_pa, est.force_n);
  est.status = inv.status;
  switch (inv.status) {
    case InversionStatus::kOk:
      est.d_m = inv.d_m;
      last_valid_d_m_ = inv.d_m;
      break;
    case InversionStatus::kSlack:
      est.d_m = 0.0;
      last_valid_d_m_ = 0.0;
      break;
    case InversionStatus::kNoPhysicalRoot:
      est.d_m = last_valid_d_m_;
      break;
  }

  // length, Eq. (1)-(2)
  est.length_m = natural_length(spring_, est.pressure_pa) + est.d_m;

  // velocity by backward difference, Eq. (11), then the optional low-pass
  const double v_raw = started_ ? (est.length_m - last_length_m_) / dt_s_ : 0.0;
  started_ = true;
  last_length_m_ = est.length_m;
  est.velocity_m_s = velocity_filter_.step(v_raw);
  return est;
}

}  // namespace pamsim
