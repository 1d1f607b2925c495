/* pamctl.h: the robot's side of a PAM reflex controller, as one freestanding C99 library:
 * per control tick, each muscle's raw readings (the pressure sensor's and the strain gauge's
 * volts, the fiber sensor's rate) and the scheduled goal pressures in; the valve commands
 * out, with each muscle's estimates and the reflexes' windows and triggers. pamsim's own
 * estimator and reflex controllers call this code, so what a lab tunes in pamsim is what its
 * board runs (docs/embedded.md). Its rules of the code, its per-tick pipeline (Yoshida and
 * Hosoda, Sec. III-C/D; Eq. (1)-(14)) and its safe behaviour on bad input are told beside
 * the code: above PAMCTL_MAX_MUSCLES, pamctl_tick and the PAMCTL_FLAG_* flags.
 */
#ifndef PAMCTL_H
#define PAMCTL_H

#include <stdbool.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Rules of the code: no heap, no I/O, no mutable globals, no recursion, every loop bounded;
 * re-entrant (all state in the caller's pamctl_state); only <math.h>, <stdint.h> and
 * <stdbool.h>. SI units throughout. `double` by default; define PAMCTL_FLOAT for `float`.
 * Build with -ffp-contract=off and without -ffast-math, as pamsim does: the equality of the
 * board's commands with the simulator's rests on it. */
#ifndef PAMCTL_MAX_MUSCLES
#define PAMCTL_MAX_MUSCLES 16
#endif

#ifdef PAMCTL_FLOAT
typedef float pamctl_real;
#else
typedef double pamctl_real;
#endif

#define PAMCTL_VERSION "1.0.0"

/* ---- the parts, each usable alone ---------------------------------------------------- */

/* First-order low-pass, exact for a zero-order hold: y += alpha (x - y), alpha =
 * 1 - exp(-2 pi fc dt) computed once by pamsim; alpha = 1 is no filter. The first step
 * returns its input. */
typedef struct {
  pamctl_real alpha;
  pamctl_real y;
  bool started;
} pamctl_lowpass;
void pamctl_lowpass_init(pamctl_lowpass* filter, pamctl_real alpha);
pamctl_real pamctl_lowpass_step(pamctl_lowpass* filter, pamctl_real x);

/* Yoshida and Hosoda's spring laws, SI coefficients (p [Pa] gauge, d [m], f [N]):
 *   Eq. (3): f = (a3 p d + a2 p + a1 d + a0) d                 coef = a0..a3
 *   Eq. (4): f = (b5 p^2 + b4 p d + b3 d^2 + b2 p + b1 d + b0) d   coef = b0..b5
 *   Eq. (5): f = (c4 p^3 + c3 p^2 d + c2 p d^2 + c1 d^2 + c0) d    coef = c0..c4
 * and Eq. (2)'s natural length l_n = m p + h. */
typedef enum { PAMCTL_LAW_EQ3 = 3, PAMCTL_LAW_EQ4 = 4, PAMCTL_LAW_EQ5 = 5 } pamctl_law;
typedef struct {
  int32_t law;            /* a pamctl_law */
  pamctl_real m_m_per_pa; /* Eq. (2) slope [m/Pa] */
  pamctl_real h_m;        /* Eq. (2) intercept [m] */
  pamctl_real coef[6];    /* paper order, unused entries 0 */
} pamctl_spring;

/* The law's number of coefficients (4, 6, 5; 0 for no law), and the exponents of p and d
 * in its term k before the common factor d (k in [0, count)). */
int32_t pamctl_law_term_count(int32_t law);
void pamctl_law_term(int32_t law, int32_t k, int32_t* p_exponent, int32_t* d_exponent);
/* f = A[0] d + A[1] d^2 + A[2] d^3 at pressure p. */
void pamctl_spring_polynomial(const pamctl_spring* spring, pamctl_real p_pa, pamctl_real a[3]);
/* The smallest positive root of a3 x^3 + a2 x^2 + a1 x - f = 0 (f > 0), or -1 when there is
 * none or an input is not finite. */
pamctl_real pamctl_smallest_positive_root(pamctl_real a3, pamctl_real a2, pamctl_real a1,
                                          pamctl_real f);

typedef enum {
  PAMCTL_INVERSION_OK = 0,     /* d > 0 solves f(p, d) = f */
  PAMCTL_INVERSION_SLACK = 1,  /* f <= 0: a slack line, d = 0 (Fig. 7) */
  PAMCTL_INVERSION_NO_ROOT = 2 /* f beyond what the law gives at p, or not finite */
} pamctl_inversion;
/* Eq. (10): d from (p, f); *d_m is finite, 0 unless PAMCTL_INVERSION_OK. */
pamctl_inversion pamctl_invert_spring(const pamctl_spring* spring, pamctl_real p_pa,
                                      pamctl_real f_n, pamctl_real* d_m);

/* ---- one muscle's estimator --------------------------------------------------------- */

typedef struct {
  pamctl_spring spring;           /* the law the estimator inverts */
  pamctl_real gauge_v_base_v;     /* Eq. (8)-(9) offset [V] */
  pamctl_real gauge_q_v_per_n;    /* Eq. (8)-(9) slope [V/N], > 0 */
  pamctl_real pressure_zero_v;    /* the pressure sensor's output at 0 Pa gauge [V] */
  pamctl_real pressure_v_per_mpa; /* its slope [V/MPa], > 0 */
  pamctl_real pressure_min_v;     /* its output range [V]: outside, a flag */
  pamctl_real pressure_max_v;
  pamctl_real gauge_min_v; /* the gauge amplifier's output range [V] */
  pamctl_real gauge_max_v;
} pamctl_muscle_config;

typedef struct {
  pamctl_lowpass pressure_filter; /* on p, sensors.pressure_lowpass_hz */
  pamctl_lowpass velocity_filter; /* on Eq. (11)'s v, reflex.lowpass_hz */
  pamctl_lowpass fiber_filter;    /* on the fiber rate, reflex.lowpass_hz */
  bool started;
  pamctl_real last_length_m;
  pamctl_real last_valid_d_m;
  int32_t missed_ticks; /* ticks held since the last valid reading */
} pamctl_muscle_state;

typedef struct {
  pamctl_real pressure_pa;        /* p as the estimate uses it (filtered if configured) */
  pamctl_real force_n;            /* Eq. (9); negative with noise (then slack); NaN: none */
  pamctl_real d_m;                /* Eq. (10), >= 0 */
  pamctl_real length_m;           /* Eq. (1) */
  pamctl_real velocity_m_s;       /* Eq. (11), filtered if configured */
  pamctl_real fiber_velocity_m_s; /* the fiber rate, filtered like v */
  int32_t inversion;              /* a pamctl_inversion */
  uint32_t flags;                 /* PAMCTL_FLAG_* of this muscle at this tick */
} pamctl_estimate;

/* The pressure sensor's line: (V - V_0) / s [MPa], in Pa. */
pamctl_real pamctl_pressure_pa(const pamctl_muscle_config* muscle, pamctl_real volts);
void pamctl_muscle_init(pamctl_muscle_state* state, pamctl_real pressure_alpha,
                        pamctl_real velocity_alpha);
/* Eq. (9)-(11) from a pressure already in Pa and the gauge's volts (no fiber, no flags). */
void pamctl_estimate_length(const pamctl_muscle_config* muscle, pamctl_real dt_s,
                            pamctl_muscle_state* state, pamctl_real pressure_pa,
                            pamctl_real gauge_v, pamctl_estimate* out);
/* One muscle's tick from its raw readings, with the bad-input rules above. */
void pamctl_estimate_muscle(const pamctl_muscle_config* muscle, pamctl_real dt_s,
                            pamctl_muscle_state* state, pamctl_real pressure_v, pamctl_real gauge_v,
                            pamctl_real fiber_rate_m_s, pamctl_estimate* out);

/* ---- the reflexes --------------------------------------------------------------------- */

/* The timing every reflex shares: a trigger opens a window of window_ticks (>= 1), the
 * trigger tick its first; never extended or restarted while it runs; then refractory_ticks
 * (>= 0) without a trigger; no trigger while t + arm_tolerance_s < arm_after_s. */
typedef struct {
  int32_t window_ticks;
  int32_t refractory_ticks;
  pamctl_real arm_after_s;
  pamctl_real arm_tolerance_s;
} pamctl_window_config;
typedef struct {
  int32_t window_left;
  int32_t refractory_left;
  bool active;
  bool triggered;
} pamctl_window;
/* One tick: true while a window is open (this tick included). */
bool pamctl_window_update(const pamctl_window_config* config, pamctl_window* window,
                          pamctl_real time_s, bool trigger);

typedef enum { PAMCTL_MODE_FOLLOW = 0, PAMCTL_MODE_LATCH = 1 } pamctl_mode;

/* The stretch (Ia) reflex, Eq. (14): dp = k v while its window is open, v > v_thr triggers;
 * v followed (>= 0) or latched at the trigger. */
typedef struct {
  pamctl_real v_thr_m_s;    /* > 0 */
  pamctl_real k_pa_s_per_m; /* >= 0 */
  int32_t mode;             /* a pamctl_mode */
  pamctl_window_config window;
} pamctl_stretch_config;
typedef struct {
  pamctl_window window;
  pamctl_real v_latched_m_s;
} pamctl_stretch_state;
pamctl_real pamctl_stretch_update(const pamctl_stretch_config* config, pamctl_stretch_state* state,
                                  pamctl_real time_s, pamctl_real velocity_m_s, bool may_trigger);

/* The tension (Ib) reflex: dp = k f while its window is open; f > f_thr, or its low-passed
 * backward-difference rate > df_thr (when df_thr > 0), triggers. A NaN tension triggers
 * nothing and leaves the rate as it was. */
typedef struct {
  pamctl_real f_thr_n;    /* > 0 */
  pamctl_real df_thr_n_s; /* >= 0, 0: off */
  pamctl_real k_pa_per_n; /* >= 0 */
  int32_t mode;           /* a pamctl_mode */
  pamctl_real rate_alpha; /* the rate's low-pass, (0, 1] */
  pamctl_window_config window;
} pamctl_tension_config;
typedef struct {
  pamctl_window window;
  pamctl_lowpass rate_filter;
  pamctl_real last_tension_n;
  bool has_last;
  pamctl_real rate_n_s;
  pamctl_real f_latched_n;
} pamctl_tension_state;
void pamctl_tension_init(const pamctl_tension_config* config, pamctl_tension_state* state);
pamctl_real pamctl_tension_update(const pamctl_tension_config* config, pamctl_tension_state* state,
                                  pamctl_real period_s, pamctl_real time_s, pamctl_real tension_n,
                                  bool may_trigger);

/* ---- the controller ------------------------------------------------------------------- */

typedef enum { PAMCTL_KIND_PASS_THROUGH = 0, PAMCTL_KIND_REFLEX = 1 } pamctl_kind;
typedef enum { PAMCTL_SENSOR_MODEL = 0, PAMCTL_SENSOR_FIBER = 1 } pamctl_sensor;

/* The reflex controller's settings (pamsim's controller kinds stretch_reflex,
 * tension_reflex and stretch_tension_reflex). */
typedef struct {
  bool enabled;                       /* reflex.enabled */
  bool stretch;                       /* the Ia reflexes run */
  bool tension;                       /* the Ib reflexes run */
  int32_t sensor;                     /* a pamctl_sensor: v for the Ia reflex */
  pamctl_real min_tension_n;          /* Ia trigger gate on the gauge (<= 0: off) */
  bool reciprocal_trigger_inhibition; /* no Ia trigger while the partner's window was open */
  bool excite_antagonist;             /* Ib output also excites the partner */
  pamctl_stretch_config ia;
  pamctl_tension_config ib;
} pamctl_reflex_config;

/* Eq. (12)-(13) for muscle j of a pair whose partner is o, before the valve's range:
 *   p_j = p_tp_j + dp_ia_j - dp_ia_o                                  (Ia reflexes alone)
 *   p_j = p_tp_j + dp_ia_j - dp_ia_o - dp_ib_j + e dp_ib_o            (with Ib, e = 0 or 1)
 * pamsim's rule for the Ib outputs (the paper gives none): every reflex reaches its own
 * muscle and the partner's, summed; e = 1 with excite_antagonist. */
pamctl_real pamctl_pair_command(const pamctl_reflex_config* rc, const pamctl_real* p_tp_pa,
                                const pamctl_real* dp_ia_pa, const pamctl_real* dp_ib_pa, int32_t j,
                                int32_t o);
/* A command clamped to the valve's range [0, p_max]; a non-finite one vents (0) and sets
 * PAMCTL_FLAG_COMMAND_VENTED in *flags. */
pamctl_real pamctl_valve_command(pamctl_real p_pa, pamctl_real p_max_pa, uint32_t* flags);

typedef struct {
  int32_t muscle_count;         /* [0, PAMCTL_MAX_MUSCLES] */
  int32_t kind;                 /* a pamctl_kind */
  pamctl_real control_period_s; /* dt of Eq. (11), > 0 */
  pamctl_real pressure_alpha;   /* the pressure low-pass, (0, 1] */
  pamctl_real velocity_alpha;   /* the velocity and fiber low-pass, (0, 1] */
  pamctl_real p_max_pa;         /* the valve's range [0, p_max] (reflex kind) */
  pamctl_reflex_config reflex;
  int32_t partner[PAMCTL_MAX_MUSCLES]; /* pair partner, -1: unpaired; symmetric */
  pamctl_muscle_config muscles[PAMCTL_MAX_MUSCLES];
} pamctl_config;

typedef struct {
  bool configured;
  pamctl_muscle_state muscles[PAMCTL_MAX_MUSCLES];
  pamctl_stretch_state ia[PAMCTL_MAX_MUSCLES];
  pamctl_tension_state ib[PAMCTL_MAX_MUSCLES];
} pamctl_state;

typedef struct {
  pamctl_real time_s; /* since the start, >= 0 */
  bool enabled;       /* false: events switched the reflexes off */
  pamctl_real pressure_v[PAMCTL_MAX_MUSCLES];
  pamctl_real gauge_v[PAMCTL_MAX_MUSCLES];
  pamctl_real fiber_rate_m_s[PAMCTL_MAX_MUSCLES]; /* 0 where no fiber sensor is fitted */
  pamctl_real p_tp_pa[PAMCTL_MAX_MUSCLES];        /* the scheduled goal pressures [Pa] */
} pamctl_input;

/* flags per muscle (pamctl_estimate.flags) and their union (pamctl_output.status) */
/* Safe behaviour on bad input (each sets a flag in pamctl_output, never undefined behaviour):
 *  - a configuration that pamctl_check_config refuses: pamctl_init returns its code and the
 *    state stays unconfigured; pamctl_tick on an unconfigured state vents every valve (0 Pa)
 *    and reports PAMCTL_STATUS_UNCONFIGURED;
 *  - a non-finite pressure or gauge reading: that muscle's estimate holds its last length
 *    (velocity 0, so no stretch reflex triggers on it), its tension is NaN (no tension
 *    reflex triggers on it) and PAMCTL_FLAG_NONFINITE_READING is set; the next valid tick's
 *    Eq. (11) spans the whole gap (its length change over the ticks since the last valid one);
 *  - a non-finite fiber rate: the filter keeps its state, the rate reads 0, the same flag;
 *  - a reading outside its sensor's configured output range: used as read, with
 *    PAMCTL_FLAG_READING_OUT_OF_RANGE;
 *  - a non-finite command (a NaN goal pressure): the valve vents (0 Pa),
 *    PAMCTL_FLAG_COMMAND_VENTED. */
#define PAMCTL_FLAG_NONFINITE_READING 0x1u
#define PAMCTL_FLAG_READING_OUT_OF_RANGE 0x2u
#define PAMCTL_FLAG_COMMAND_VENTED 0x4u
#define PAMCTL_STATUS_UNCONFIGURED 0x100u

typedef struct {
  pamctl_real p_cmd_pa[PAMCTL_MAX_MUSCLES];     /* the valve commands [Pa] gauge */
  pamctl_real velocity_m_s[PAMCTL_MAX_MUSCLES]; /* the v each muscle's control acted on */
  bool ia_active[PAMCTL_MAX_MUSCLES];
  bool ia_triggered[PAMCTL_MAX_MUSCLES];
  bool ib_active[PAMCTL_MAX_MUSCLES];
  bool ib_triggered[PAMCTL_MAX_MUSCLES];
  pamctl_estimate estimates[PAMCTL_MAX_MUSCLES];
  uint32_t status;
} pamctl_output;

/* 0 if the configuration can run, else the code of its first bad field (pamctl_config_error
 * names it). */
int32_t pamctl_check_config(const pamctl_config* config);
const char* pamctl_config_error(int32_t code);
/* Checks the configuration and resets the state; returns pamctl_check_config's code. */
int32_t pamctl_init(const pamctl_config* config, pamctl_state* state);
/* Resets the state for a configuration its caller has checked (pamsim, whose own checks
 * name the scenario's keys). */
void pamctl_reset(const pamctl_config* config, pamctl_state* state);
/* One control tick: estimates, reflexes, commands. For each muscle j (Yoshida and Hosoda's
 * pipeline, Sec. III-C/D):
 *   p   = lowpass((V_p - V_0) / s_p)         the pressure sensor's line, [MPa] to [Pa]
 *   f   = (V_g - V_base) / q                 Eq. (9), the strain gauge's Eq. (8) inverted
 *   d   = smallest d >= 0 with f(p, d) = f   Eq. (3)-(5) inverted, Eq. (10)
 *   l   = m p + h + d                        Eq. (1)-(2)
 *   v   = lowpass((l_j - l_{j-1}) / dt)      Eq. (11)
 * then the reflexes of each antagonistic pair (Ia: Eq. (14) on v; Ib: on f) and the commands
 * of Eq. (12)-(13), clamped to the valve's range [0, p_max]. */
void pamctl_tick(const pamctl_config* config, pamctl_state* state, const pamctl_input* in,
                 pamctl_output* out);
/* The controller alone, on estimates already in out->estimates (how pamsim runs its sensing
 * and its controller as separate floors): reflexes and commands. */
void pamctl_control(const pamctl_config* config, pamctl_state* state, pamctl_real time_s,
                    bool enabled, const pamctl_real* p_tp_pa, pamctl_output* out);

#ifdef __cplusplus
}
#endif

#endif /* PAMCTL_H */
