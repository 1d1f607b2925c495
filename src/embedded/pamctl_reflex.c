/* pamctl_reflex.c: the reflexes of one muscle: the window every reflex shares (trigger,
 * window, refractory time, arming), the stretch (Ia) reflex of Yoshida and Hosoda's
 * Eq. (14) on the velocity, and the tension (Ib) reflex on the gauge's tension. */
#include "pamctl_math.h"

bool pamctl_window_update(const pamctl_window_config* config, pamctl_window* window,
                          pamctl_real time_s, bool trigger) {
  /* idle: count down the refractory period, else look for a trigger */
  window->triggered = false;
  if (window->window_left == 0) {
    window->active = false;
    if (window->refractory_left > 0) {
      --window->refractory_left;
      return false;
    }
    const bool armed = time_s + config->arm_tolerance_s >= config->arm_after_s;
    if (!armed || !trigger) return false;
    /* trigger: this tick is the first of the window */
    window->triggered = true;
    window->window_left = config->window_ticks;
  }
  window->active = true;
  if (--window->window_left == 0) window->refractory_left = config->refractory_ticks;
  return true;
}

pamctl_real pamctl_stretch_update(const pamctl_stretch_config* config, pamctl_stretch_state* state,
                                  pamctl_real time_s, pamctl_real velocity_m_s, bool may_trigger) {
  const bool over = velocity_m_s > config->v_thr_m_s;
  if (!pamctl_window_update(&config->window, &state->window, time_s, may_trigger && over)) {
    return PAMCTL_R(0.0);
  }
  if (state->window.triggered) state->v_latched_m_s = velocity_m_s;
  /* an open window: dp = k v, Eq. (14), with v followed (>= 0) or latched */
  const pamctl_real v = config->mode == PAMCTL_MODE_LATCH
                            ? state->v_latched_m_s
                            : (velocity_m_s > PAMCTL_R(0.0) ? velocity_m_s : PAMCTL_R(0.0));
  return config->k_pa_s_per_m * v;
}

void pamctl_tension_init(const pamctl_tension_config* config, pamctl_tension_state* state) {
  state->window.window_left = 0;
  state->window.refractory_left = 0;
  state->window.active = false;
  state->window.triggered = false;
  pamctl_lowpass_init(&state->rate_filter, config->rate_alpha);
  state->last_tension_n = PAMCTL_R(0.0);
  state->has_last = false;
  state->rate_n_s = PAMCTL_R(0.0);
  state->f_latched_n = PAMCTL_R(0.0);
}

pamctl_real pamctl_tension_update(const pamctl_tension_config* config, pamctl_tension_state* state,
                                  pamctl_real period_s, pamctl_real time_s, pamctl_real tension_n,
                                  bool may_trigger) {
  /* the rate by backward difference, low-passed; a missing reading (NaN) triggers nothing
   * and leaves the rate as it was */
  const bool reading = pamctl_isfinite(tension_n);
  if (reading) {
    const pamctl_real raw_rate =
        state->has_last ? (tension_n - state->last_tension_n) / period_s : PAMCTL_R(0.0);
    state->rate_n_s = pamctl_lowpass_step(&state->rate_filter, raw_rate);
    state->last_tension_n = tension_n;
    state->has_last = true;
  }
  const bool over =
      reading && (tension_n > config->f_thr_n ||
                  (config->df_thr_n_s > PAMCTL_R(0.0) && state->rate_n_s > config->df_thr_n_s));
  if (!pamctl_window_update(&config->window, &state->window, time_s, may_trigger && over)) {
    return PAMCTL_R(0.0);
  }
  if (state->window.triggered) state->f_latched_n = tension_n;
  /* an open window: dp = k f, f followed (>= 0) or latched */
  const pamctl_real f = config->mode == PAMCTL_MODE_LATCH
                            ? state->f_latched_n
                            : (tension_n > PAMCTL_R(0.0) ? tension_n : PAMCTL_R(0.0));
  return config->k_pa_per_n * f;
}
