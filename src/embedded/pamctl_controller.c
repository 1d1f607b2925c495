/* pamctl_controller.c: the controller's tick: every muscle's estimate, its reflexes behind
 * their gates, and the commands of Yoshida and Hosoda's Eq. (12)-(13) for each antagonistic
 * pair (with the tension reflexes, pamsim's extension of them), clamped to the valve's range;
 * or the scheduled commands passed through. */
#include "pamctl_math.h"

pamctl_real pamctl_valve_command(pamctl_real x, pamctl_real hi, uint32_t* flags) {
  if (!pamctl_isfinite(x)) {
    *flags |= PAMCTL_FLAG_COMMAND_VENTED;
    return PAMCTL_R(0.0);
  }
  return x < PAMCTL_R(0.0) ? PAMCTL_R(0.0) : (hi < x ? hi : x);
}

/* muscle j's reflexes at this tick, into dp_ia[j] and dp_ib[j] */
static void run_reflexes(const pamctl_config* config, pamctl_state* state, int j,
                         pamctl_real time_s, bool enabled, const bool* was_active,
                         pamctl_real* dp_ia, pamctl_real* dp_ib, pamctl_output* out) {
  const pamctl_reflex_config* rc = &config->reflex;
  const pamctl_real force_n = out->estimates[j].force_n;
  if (rc->stretch) {
    /* the stretch reflex, Eq. (14), behind the tension and reciprocal gates */
    const bool loaded = rc->min_tension_n <= PAMCTL_R(0.0) || force_n >= rc->min_tension_n;
    const bool other_quiet = !(rc->reciprocal_trigger_inhibition && was_active[config->partner[j]]);
    const pamctl_real dp = pamctl_stretch_update(
        &rc->ia, &state->ia[j], time_s, out->velocity_m_s[j], enabled && loaded && other_quiet);
    if (enabled) {
      dp_ia[j] = dp;
      out->ia_active[j] = state->ia[j].window.active;
      out->ia_triggered[j] = state->ia[j].window.triggered;
    }
  }
  if (rc->tension) {
    /* the tension reflex on the gauge's tension, Eq. (8)-(9) */
    const pamctl_real dp = pamctl_tension_update(&rc->ib, &state->ib[j], config->control_period_s,
                                                 time_s, force_n, enabled);
    if (enabled) {
      dp_ib[j] = dp;
      out->ib_active[j] = state->ib[j].window.active;
      out->ib_triggered[j] = state->ib[j].window.triggered;
    }
  }
}

pamctl_real pamctl_pair_command(const pamctl_reflex_config* rc, const pamctl_real* p_tp_pa,
                                const pamctl_real* dp_ia, const pamctl_real* dp_ib, int32_t j,
                                int32_t o) {
  /* its own excitation up, the other's inhibition down; with the tension reflexes, its own
   * Ib output down and, with excite_antagonist, the partner's up */
  if (!rc->tension) return p_tp_pa[j] + dp_ia[j] - dp_ia[o];
  const pamctl_real e = rc->excite_antagonist ? PAMCTL_R(1.0) : PAMCTL_R(0.0);
  return p_tp_pa[j] + dp_ia[j] - dp_ia[o] - dp_ib[j] + e * dp_ib[o];
}

/* the reflex kind: reflexes per paired muscle, then the commands */
static void reflex_control(const pamctl_config* config, pamctl_state* state, pamctl_real time_s,
                           bool enabled, const pamctl_real* p_tp_pa, pamctl_output* out) {
  const int n = config->muscle_count;
  const pamctl_reflex_config* rc = &config->reflex;
  bool was_active[PAMCTL_MAX_MUSCLES];
  pamctl_real dp_ia[PAMCTL_MAX_MUSCLES], dp_ib[PAMCTL_MAX_MUSCLES];
  for (int j = 0; j < n; ++j) was_active[j] = state->ia[j].window.active;

  for (int j = 0; j < n; ++j) {
    /* the velocity the stretch reflex sees */
    const pamctl_estimate* est = &out->estimates[j];
    out->velocity_m_s[j] =
        rc->sensor == PAMCTL_SENSOR_FIBER ? est->fiber_velocity_m_s : est->velocity_m_s;
    dp_ia[j] = dp_ib[j] = PAMCTL_R(0.0);
    /* switched off by events, windows and refractory times run out without acting */
    if (!rc->enabled || config->partner[j] < 0) continue;
    run_reflexes(config, state, j, time_s, enabled, was_active, dp_ia, dp_ib, out);
  }

  /* each pair's commands, unpaired muscles their schedule; all within the valve's range */
  for (int j = 0; j < n; ++j) {
    const int o = config->partner[j];
    const pamctl_real p = o < 0 ? p_tp_pa[j] : pamctl_pair_command(rc, p_tp_pa, dp_ia, dp_ib, j, o);
    out->p_cmd_pa[j] = pamctl_valve_command(p, config->p_max_pa, &out->estimates[j].flags);
  }
}

void pamctl_control(const pamctl_config* config, pamctl_state* state, pamctl_real time_s,
                    bool enabled, const pamctl_real* p_tp_pa, pamctl_output* out) {
  const int n = config->muscle_count;
  for (int j = 0; j < n; ++j) {
    out->ia_active[j] = out->ia_triggered[j] = false;
    out->ib_active[j] = out->ib_triggered[j] = false;
  }
  if (config->kind == PAMCTL_KIND_REFLEX) {
    reflex_control(config, state, time_s, enabled, p_tp_pa, out);
  } else {
    /* pass-through: the schedule, unclamped; the estimate's velocity logged */
    for (int j = 0; j < n; ++j) {
      out->velocity_m_s[j] = out->estimates[j].velocity_m_s;
      out->p_cmd_pa[j] = p_tp_pa[j];
      if (!pamctl_isfinite(p_tp_pa[j])) {
        out->p_cmd_pa[j] = PAMCTL_R(0.0);
        out->estimates[j].flags |= PAMCTL_FLAG_COMMAND_VENTED;
      }
    }
  }
  out->status = 0u;
  for (int j = 0; j < n; ++j) out->status |= out->estimates[j].flags;
}

int32_t pamctl_init(const pamctl_config* config, pamctl_state* state) {
  state->configured = false;
  const int32_t code = pamctl_check_config(config);
  if (code == 0) pamctl_reset(config, state);
  return code;
}

void pamctl_reset(const pamctl_config* config, pamctl_state* state) {
  for (int j = 0; j < PAMCTL_MAX_MUSCLES; ++j) {
    pamctl_muscle_init(&state->muscles[j], config->pressure_alpha, config->velocity_alpha);
    state->ia[j].window.window_left = state->ia[j].window.refractory_left = 0;
    state->ia[j].window.active = state->ia[j].window.triggered = false;
    state->ia[j].v_latched_m_s = PAMCTL_R(0.0);
    pamctl_tension_init(&config->reflex.ib, &state->ib[j]);
  }
  state->configured = true;
}

void pamctl_tick(const pamctl_config* config, pamctl_state* state, const pamctl_input* in,
                 pamctl_output* out) {
  /* an unconfigured controller vents every valve */
  if (!state->configured) {
    for (int j = 0; j < PAMCTL_MAX_MUSCLES; ++j) out->p_cmd_pa[j] = PAMCTL_R(0.0);
    out->status = PAMCTL_STATUS_UNCONFIGURED;
    return;
  }
  /* every muscle's estimate, Eq. (9)-(11), then the controller */
  for (int j = 0; j < config->muscle_count; ++j) {
    pamctl_estimate_muscle(&config->muscles[j], config->control_period_s, &state->muscles[j],
                           in->pressure_v[j], in->gauge_v[j], in->fiber_rate_m_s[j],
                           &out->estimates[j]);
  }
  pamctl_control(config, state, in->time_s, in->enabled, in->p_tp_pa, out);
}
