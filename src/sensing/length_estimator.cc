// length_estimator.cc: Eq. (9)-(11) on measured pressure and gauge voltage.
#include "sensing/length_estimator.h"

#include <cassert>

namespace pamsim {

pamctl_muscle_config embedded_muscle(const SpringModel& spring, const StrainGaugeParams& gauge) {
  pamctl_muscle_config muscle{};
  muscle.spring = embedded_spring(spring);
  muscle.gauge_v_base_v = gauge.v_base_v;
  muscle.gauge_q_v_per_n = gauge.q_v_per_n;
  return muscle;
}

LengthEstimator::LengthEstimator(const SpringModel& spring, const StrainGaugeParams& gauge,
                                 const LengthEstimatorParams& params, double sample_period_s)
    : muscle_(embedded_muscle(spring, gauge)), dt_s_(sample_period_s) {
  assert(gauge.q_v_per_n > 0.0);
  pamctl_muscle_init(&state_, lowpass_alpha(params.pressure_lowpass_hz, sample_period_s),
                     lowpass_alpha(params.velocity_lowpass_hz, sample_period_s));
}

LengthEstimate LengthEstimator::update(double pressure_meas_pa, double gauge_v) {
  // Eq. (9)-(11): the embedded controller's estimator
  pamctl_estimate e{};
  pamctl_estimate_length(&muscle_, dt_s_, &state_, pressure_meas_pa, gauge_v, &e);
  LengthEstimate est;
  est.pressure_pa = e.pressure_pa;
  est.force_n = e.force_n;
  est.d_m = e.d_m;
  est.status = inversion_status(static_cast<pamctl_inversion>(e.inversion));
  est.length_m = e.length_m;
  est.velocity_m_s = e.velocity_m_s;
  return est;
}

}  // namespace pamsim
