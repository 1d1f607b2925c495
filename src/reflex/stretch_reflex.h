// stretch_reflex.h: the stretch reflex of one muscle and the reflex command law of the paper
// (Sec. III-D, Eq. (12)-(14); Takahashi et al.'s alpha-motor-neuron design): Eq. (14) at
// StretchReflex, Eq. (12)-(13) at reflex_commands, the window's timing at ReflexWindow.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "embedded/pamctl.h"

namespace pamsim {

// Mode (the paper does not say which): "follow" uses the current v during the window,
// clamped >= 0; "latch" holds the v that triggered. Default: follow. A prototype of the
// falling-mass arm found that following gives the full drop reduction (~3.6 deg with the
// ISO 6358 chamber) and lets the command fall back within ~50 ms once the stretch stops,
// while latching the peak for the whole 200 ms overshoots the arm to about -11 deg with the fiber
// sensor; follow is also the closer analogue of a spindle whose discharge tracks the stretch rate.
enum class ReflexMode { kFollow, kLatch };

// "follow" | "latch"
const char* to_string(ReflexMode mode);
// Throws InputError naming `key` (reflex.mode, reflex.ib.mode) on anything else.
ReflexMode parse_reflex_mode(const std::string& name, const std::string& key = "reflex.mode");

// The stretch reflex's parameters, SI; their scenario keys reflex.* (paper units, named) are
// rows of reflex_keys.h. Defaults: Table II's model-based reflex.
struct StretchReflexParams {
  double v_thr_m_s = 0.070;  // V_thr > 0 [m/s], reflex.v_thr_mm_s = 70 (fiber 25)
  // k >= 0 [Pa/(m/s)], reflex.k_MPa_s_per_mm = 1/800 (fiber 1/300): 1/800 MPa per mm/s
  double k_pa_s_per_m = 1e9 / 800.0;
  double duration_s = 0.2;                // reflex.duration_s, >= one control period
  ReflexMode mode = ReflexMode::kFollow;  // reflex.mode
  // reflex.refractory_s >= 0. Default 0.5 s: on the ideal plant (drop_mass_ideal.toml) the
  // arm rings at ~5 Hz after the impact, so the rebound stretches come ~200 ms apart and the
  // fiber reflex (25 mm/s) re-fired on them; 0.5 s after the 0.2 s window covers the first
  // three rebounds. The physical plant (drop_mass.toml) swings at ~1.9 Hz and its braid
  // friction damps the swing within a cycle: there this gate alone changes nothing
  // measurable (docs/findings.md, the gates table). A pamsim addition: 0 switches it off.
  double refractory_s = 0.5;
  // reflex.arm_after_s >= 0. Default 0.1 s: three time constants (tau = 32 ms) of a 5 Hz
  // (cut-off) pressure low-pass when one is on (sensors.pressure_lowpass_hz), and still
  // before a mass dropped from 14 cm at t = 0 lands (0.17 s). A pamsim addition: 0 switches it off.
  double arm_after_s = 0.1;
};

// The timing every reflex shares (the stretch reflex here, the tension reflex of
// tension_reflex.h): a trigger opens a window of round(duration_s / dt) ticks (>= 1), the
// trigger tick its first; a window is never extended or restarted while it runs; after it,
// round(refractory_s / dt) ticks refractory (0 allowed); no trigger while t < arm_after_s
// (filters and the plant settling at the start). All in whole control ticks; the ticks are
// counted by the embedded controller's code (pamctl_window_update, src/embedded/pamctl.h);
// embedded_window computes its tick counts, once.
pamctl_window_config embedded_window(double duration_s, double refractory_s, double arm_after_s,
                                     double control_period_s);
class ReflexWindow {
 public:
  // refractory_s, arm_after_s >= 0 and control_period_s > 0 (asserted); a window lasts at
  // least one tick whatever duration_s.
  ReflexWindow(double duration_s, double refractory_s, double arm_after_s, double control_period_s);

  // One control tick at time_s: opens a window if `trigger` and the reflex is idle, armed
  // and not refractory. Returns true while a window is open (this tick included).
  bool update(double time_s, bool trigger);

  bool active() const { return window_.active; }
  // True if the last update() opened a window.
  bool triggered() const { return window_.triggered; }

 private:
  pamctl_window_config config_;
  pamctl_window window_{};
};

// The stretch reflex as the embedded controller holds it (SI, its window in ticks).
pamctl_stretch_config embedded_stretch(const StretchReflexParams& params, double control_period_s);

// Each muscle has its own reflex. When its velocity v (positive = being stretched) exceeds
// V_thr, the reflex fires for `duration_s` (200 ms in the paper: 20 ticks at 100 Hz) and
// outputs, Eq. (14),
//   dp = dp_exci = dp_inhi = k v,     dp [MPa] = k [MPa per mm/s] * v [mm/s]
// (the paper prints k's unit as "GPa s"; dimensionally it is MPa/(mm/s) = GPa s/m:
// 100 mm/s with k = 1/800 gives 0.125 MPa).
class StretchReflex {
 public:
  // control_period_s > 0. Parameters must have passed validate() (asserted).
  StretchReflex(const StretchReflexParams& params, double control_period_s);

  // One control tick at time_s with this muscle's velocity [m/s] (positive = stretching).
  // Returns dp = k v [Pa], >= 0, to add to this muscle's command and subtract from the
  // other's; 0 when the reflex is not active. `may_trigger` = false suppresses a new
  // trigger at this tick (a running window goes on): the controller's gates.
  double update(double time_s, double velocity_m_s, bool may_trigger = true);

  bool active() const { return state_.window.active; }
  // True if the last update() opened a window (the controller keeps the trigger times).
  bool triggered() const { return state_.window.triggered; }

 private:
  pamctl_stretch_config config_;
  pamctl_stretch_state state_{};
};

// The two muscles of an antagonistic pair, in the order of Eq. (12)-(13).
enum PairRole : int { kAgonist = 0, kAntagonist = 1 };
using PairValues = std::array<double, 2>;  // indexed by PairRole

// Eq. (12)-(13): a pair's commands [Pa] from its goal pressures and the two reflexes' dp
// [Pa], each clamped to [0, p_max_pa]:
//   p_ago  = p_tp_ago  + dp_exci_ago  - dp_inhi_anta
//   p_anta = p_tp_anta + dp_exci_anta - dp_inhi_ago
// so a muscle's own reflex raises its command and lowers the other's (reciprocal
// inhibition).
PairValues reflex_commands(const PairValues& p_tp_pa, const PairValues& dp_pa, double p_max_pa);

}  // namespace pamsim
