// tension_reflex.h: the Ib reflex of one muscle, autogenic inhibition from its force sensor
// alone: the Golgi tendon organ's analogue, the step Yoshida and Hosoda name after the Ia
// stretch reflex (Sec. V: "the Ia reflex and the Ib reflex
// coexist ... using only pressure and force sensors"). pamsim's design, after Eq. (12)-(14)
// of the Ia reflex, as the paper gives none: TensionReflex.
#pragma once

#include "sensing/lowpass_filter.h"
#include "reflex/stretch_reflex.h"

namespace pamsim {

// The Ib reflex's parameters, SI; their scenario keys reflex.ib.* (paper units, named) are
// rows of reflex_keys.h. No paper gives an Ib threshold or gain for a PAM: a scenario with
// the Ib reflex must give f_thr_N and k_MPa_per_N (the values here are placeholders for
// tests).
struct TensionReflexParams {
  double f_thr_N = 60.0;                  // reflex.ib.f_thr_N > 0, the tension threshold
  double df_thr_N_s = 0.0;                // reflex.ib.df_thr_N_s >= 0, rate threshold (0: off)
  double k_pa_per_n = 2000.0;             // reflex.ib.k_MPa_per_N >= 0, the gain [Pa/N]
  double duration_s = 0.2;                // reflex.ib.duration_s, >= one control period
  ReflexMode mode = ReflexMode::kFollow;  // reflex.ib.mode
  double refractory_s = 0.0;              // reflex.ib.refractory_s >= 0
  double arm_after_s = 0.1;               // reflex.ib.arm_after_s >= 0
  double rate_lowpass_hz = 10.0;          // reflex.ib.rate_lowpass_hz: 0 or up to Nyquist
  bool excite_antagonist = false;         // reflex.ib.excite_antagonist
};

// Checks every field, throwing InputError "reflex.ib.<key> must be ..., got <value>".
void validate(const TensionReflexParams& params, double control_hz);

// The tension reflex as the embedded controller holds it (SI, its window in ticks, its rate
// filter's factor).
pamctl_tension_config embedded_tension(const TensionReflexParams& params, double control_period_s);

// A tendon organ fires with the tension of its muscle and inhibits that muscle's motor
// neurons (and, through interneurons, excites the antagonist's). Here, after Eq. (12)-(14)
// of the Ia reflex: when the measured tension f (Eq. (8)-(9), the strain gauge) exceeds
// F_thr, or its rate df/dt exceeds dF_thr (optional, low-passed), the reflex fires for
// `duration_s` and outputs
//   dp_ib = k_ib f,        dp [MPa] = k_ib [MPa/N] * f [N],
// f followed (>= 0) during the window or latched at the trigger (reflex.ib.mode), to subtract
// from the muscle's own command and, with excite_antagonist, to add to its pair partner's.
// The window, refractory time and arming are the Ia reflex's (ReflexWindow,
// stretch_reflex.h). How the Ia and Ib outputs combine: stretch_reflex_controller.h.
//
// pamsim's choices where the paper gives no Ib design: the output is proportional to the
// whole tension, as Eq. (14)'s is to the whole velocity (a tendon organ's discharge grows with
// tension from its threshold on); the rate trigger catches an impact's rising tension before
// it peaks, as the Ia reflex's velocity does for length.
class TensionReflex {
 public:
  // Parameters must have passed validate() (asserted where cheap).
  TensionReflex(const TensionReflexParams& params, double control_period_s);

  // One control tick at time_s with this muscle's measured tension [N]. Returns
  // dp_ib = k f [Pa] >= 0 while the window is open, else 0. `may_trigger` = false
  // suppresses a new trigger at this tick.
  double update(double time_s, double tension_n, bool may_trigger = true);

  bool active() const { return state_.window.active; }
  bool triggered() const { return state_.window.triggered; }
  // The low-passed tension rate of the last update [N/s] (0 at the first).
  double rate_n_s() const { return state_.rate_n_s; }

 private:
  pamctl_tension_config config_;
  double period_s_;
  pamctl_tension_state state_{};
};

}  // namespace pamsim
