// tension_reflex.cc: see tension_reflex.h.
#include "reflex/tension_reflex.h"

#include <cassert>
#include <cmath>

#include "reflex/reflex_keys.h"
#include "sensing/checks.h"

namespace pamsim {

void validate(const TensionReflexParams& p, double control_hz) {
  using namespace checks;
  TensionReflexParams fields = p;   // the rows' ranges and choices
  check_key_rows(tension_reflex_key_table(&fields));
  require_window("reflex.ib", p.duration_s, p.refractory_s, p.arm_after_s, 1.0 / control_hz);
  require_cutoff("reflex.ib.rate_lowpass_hz", p.rate_lowpass_hz, control_hz);
}

TensionReflex::TensionReflex(const TensionReflexParams& params, double control_period_s)
    : f_thr_n_(params.f_thr_N),
      df_thr_n_s_(params.df_thr_N_s),
      k_pa_per_n_(params.k_pa_per_n),
      mode_(params.mode),
      period_s_(control_period_s),
      window_(params.duration_s, params.refractory_s, params.arm_after_s, control_period_s),
      rate_filter_(params.rate_lowpass_hz, control_period_s) {
  assert(params.f_thr_N > 0.0 && params.k_pa_per_n >= 0.0 && params.df_thr_N_s >= 0.0);
}

double TensionReflex::update(double time_s, double tension_n, bool may_trigger) {
  // the rate by backward difference, low-passed; a missing reading (NaN) triggers nothing
  // and leaves the rate as it was
  const bool reading = std::isfinite(tension_n);
  if (reading) {
    const double raw_rate = has_last_ ? (tension_n - last_tension_n_) / period_s_ : 0.0;
    rate_n_s_ = rate_filter_.step(raw_rate);
    last_tension_n_ = tension_n;
    has_last_ = true;
  }
  const bool over =
      reading && (tension_n > f_thr_n_ || (df_thr_n_s_ > 0.0 && rate_n_s_ > df_thr_n_s_));
  if (!window_.update(time_s, may_trigger && over)) return 0.0;
  if (window_.triggered()) f_latched_n_ = tension_n;
  const double f = mode_ == ReflexMode::kLatch ? f_latched_n_
                 : (tension_n > 0.0 ? tension_n : 0.0);
  return k_pa_per_n_ * f;
}

}  // namespace pamsim
