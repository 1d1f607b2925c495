/* pamctl_estimator.c: one muscle's readings to its estimates: the pressure sensor's line, the
 * strain gauge's Eq. (9), the spring law inverted for d, Eq. (10), the length of Eq. (1)-(2),
 * the velocity of Eq. (11), and the low-passes on pressure, velocity and the fiber rate. */
#include "pamctl_math.h"

/* the pressure sensor's line is in MPa per volt; the library's pressures are Pa */
#define PAMCTL_PA_PER_MPA PAMCTL_R(1e6)

void pamctl_lowpass_init(pamctl_lowpass* filter, pamctl_real alpha) {
  filter->alpha = alpha;
  filter->y = PAMCTL_R(0.0);
  filter->started = false;
}

pamctl_real pamctl_lowpass_step(pamctl_lowpass* filter, pamctl_real x) {
  /* first sample: start at the input, no transient */
  if (!filter->started) {
    filter->y = x;
    filter->started = true;
    return filter->y;
  }
  /* exact zero-order-hold update of tau dy/dt = x - y */
  filter->y += filter->alpha * (x - filter->y);
  return filter->y;
}

pamctl_real pamctl_pressure_pa(const pamctl_muscle_config* muscle, pamctl_real volts) {
  return (volts - muscle->pressure_zero_v) / muscle->pressure_v_per_mpa * PAMCTL_PA_PER_MPA;
}

void pamctl_muscle_init(pamctl_muscle_state* state, pamctl_real pressure_alpha,
                        pamctl_real velocity_alpha) {
  pamctl_lowpass_init(&state->pressure_filter, pressure_alpha);
  pamctl_lowpass_init(&state->velocity_filter, velocity_alpha);
  pamctl_lowpass_init(&state->fiber_filter, velocity_alpha);
  state->started = false;
  state->last_length_m = PAMCTL_R(0.0);
  state->last_valid_d_m = PAMCTL_R(0.0);
  state->missed_ticks = 0;
}

void pamctl_estimate_length(const pamctl_muscle_config* muscle, pamctl_real dt_s,
                            pamctl_muscle_state* state, pamctl_real pressure_pa,
                            pamctl_real gauge_v, pamctl_estimate* out) {
  /* pressure, optionally low-passed, and force from the gauge, Eq. (9) */
  out->pressure_pa = pamctl_lowpass_step(&state->pressure_filter, pressure_pa);
  out->force_n = (gauge_v - muscle->gauge_v_base_v) / muscle->gauge_q_v_per_n;

  /* deformation by inverting the spring law, Eq. (10): slack gives d = 0; a force beyond
   * the law holds the last valid d rather than read as a jump */
  pamctl_real d = PAMCTL_R(0.0);
  const pamctl_inversion status =
      pamctl_invert_spring(&muscle->spring, out->pressure_pa, out->force_n, &d);
  out->inversion = (int32_t)status;
  if (status == PAMCTL_INVERSION_NO_ROOT) d = state->last_valid_d_m;
  state->last_valid_d_m = d;
  out->d_m = d;

  /* length, Eq. (1)-(2) */
  out->length_m = muscle->spring.m_m_per_pa * out->pressure_pa + muscle->spring.h_m + d;

  /* velocity by backward difference, Eq. (11), over the ticks since the last valid one,
   * then the optional low-pass */
  const pamctl_real span_s =
      state->missed_ticks == 0 ? dt_s : dt_s * (pamctl_real)(state->missed_ticks + 1);
  const pamctl_real v_raw =
      state->started ? (out->length_m - state->last_length_m) / span_s : PAMCTL_R(0.0);
  state->started = true;
  state->missed_ticks = 0;
  state->last_length_m = out->length_m;
  out->velocity_m_s = pamctl_lowpass_step(&state->velocity_filter, v_raw);
}

/* a reading outside [lo, hi] */
static bool outside(pamctl_real v, pamctl_real lo, pamctl_real hi) { return v < lo || v > hi; }

/* a muscle whose pressure or gauge reading is not finite: the last length held, still */
static void hold_estimate(const pamctl_muscle_config* muscle, const pamctl_muscle_state* state,
                          pamctl_real gauge_v, pamctl_estimate* out) {
  out->pressure_pa = state->pressure_filter.y;
  out->force_n = (gauge_v - muscle->gauge_v_base_v) / muscle->gauge_q_v_per_n;
  out->d_m = state->last_valid_d_m;
  out->length_m = state->last_length_m;
  out->velocity_m_s = PAMCTL_R(0.0);
  out->inversion = PAMCTL_INVERSION_NO_ROOT;
}

void pamctl_estimate_muscle(const pamctl_muscle_config* muscle, pamctl_real dt_s,
                            pamctl_muscle_state* state, pamctl_real pressure_v, pamctl_real gauge_v,
                            pamctl_real fiber_rate_m_s, pamctl_estimate* out) {
  out->flags = 0u;
  /* readings outside their sensor's range are used, and flagged */
  if (outside(pressure_v, muscle->pressure_min_v, muscle->pressure_max_v) ||
      outside(gauge_v, muscle->gauge_min_v, muscle->gauge_max_v)) {
    out->flags |= PAMCTL_FLAG_READING_OUT_OF_RANGE;
  }
  /* Eq. (9)-(11), or the last length held when a reading is missing */
  if (pamctl_isfinite(pressure_v) && pamctl_isfinite(gauge_v)) {
    pamctl_estimate_length(muscle, dt_s, state, pamctl_pressure_pa(muscle, pressure_v), gauge_v,
                           out);
  } else {
    out->flags |= PAMCTL_FLAG_NONFINITE_READING;
    hold_estimate(muscle, state, gauge_v, out);
    if (state->missed_ticks < INT32_MAX - 1) ++state->missed_ticks;
  }
  /* the fiber's low-passed rate; a missing one reads 0 and leaves the filter as it was */
  if (pamctl_isfinite(fiber_rate_m_s)) {
    out->fiber_velocity_m_s = pamctl_lowpass_step(&state->fiber_filter, fiber_rate_m_s);
  } else {
    out->flags |= PAMCTL_FLAG_NONFINITE_READING;
    out->fiber_velocity_m_s = PAMCTL_R(0.0);
  }
}
