// tension_reflex.cc: see tension_reflex.h.
#include "reflex/tension_reflex.h"

#include <cassert>
#include <cmath>

#include "reflex/reflex_keys.h"
#include "sensing/checks.h"

namespace pamsim {

void validate(const TensionReflexParams& p, double control_hz) {
  using namespace checks;
  TensionReflexParams fields = p;  // the rows' ranges and choices
  check_key_rows(tension_reflex_key_table(&fields));
  require_window("reflex.ib", p.duration_s, p.refractory_s, p.arm_after_s, 1.0 / control_hz);
  require_cutoff("reflex.ib.rate_lowpass_hz", p.rate_lowpass_hz, control_hz);
}

pamctl_tension_config embedded_tension(const TensionReflexParams& params, double control_period_s) {
  pamctl_tension_config config{};
  config.f_thr_n = params.f_thr_N;
  config.df_thr_n_s = params.df_thr_N_s;
  config.k_pa_per_n = params.k_pa_per_n;
  config.mode = params.mode == ReflexMode::kLatch ? PAMCTL_MODE_LATCH : PAMCTL_MODE_FOLLOW;
  config.rate_alpha = lowpass_alpha(params.rate_lowpass_hz, control_period_s);
  config.window =
      embedded_window(params.duration_s, params.refractory_s, params.arm_after_s, control_period_s);
  return config;
}

TensionReflex::TensionReflex(const TensionReflexParams& params, double control_period_s)
    : config_(embedded_tension(params, control_period_s)), period_s_(control_period_s) {
  assert(params.f_thr_N > 0.0 && params.k_pa_per_n >= 0.0 && params.df_thr_N_s >= 0.0);
  pamctl_tension_init(&config_, &state_);
}

double TensionReflex::update(double time_s, double tension_n, bool may_trigger) {
  // the embedded controller's tension reflex
  return pamctl_tension_update(&config_, &state_, period_s_, time_s, tension_n, may_trigger);
}

}  // namespace pamsim
