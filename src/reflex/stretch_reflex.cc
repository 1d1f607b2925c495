// stretch_reflex.cc: trigger, window, refractory and arming of one muscle's reflex;
// Eq. (12)-(14).
#include "reflex/stretch_reflex.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "base/enum_names.h"
#include "base/input_error.h"
#include "base/units.h"

namespace pamsim {

namespace {
constexpr EnumName<ReflexMode> kModeNames[] = {{ReflexMode::kFollow, "follow"},
                                               {ReflexMode::kLatch, "latch"}};
}  // namespace

const char* to_string(ReflexMode mode) { return name_of(kModeNames, mode); }

ReflexMode parse_reflex_mode(const std::string& name) {
  return parse_name(kModeNames, name, "reflex.mode");
}

StretchReflex::StretchReflex(const StretchReflexParams& params, double control_period_s)
    : v_thr_m_s_(units::mm_to_m(params.v_thr_mm_s)),
      // MPa per mm/s -> Pa per m/s
      k_pa_s_per_m_(params.k_MPa_s_per_mm * units::kPaPerMPa / units::kMPerMm),
      mode_(params.mode),
      arm_after_s_(params.arm_after_s),
      window_ticks_(std::max(1, static_cast<int>(std::lround(params.duration_s /
                                                              control_period_s)))),
      refractory_ticks_(static_cast<int>(std::lround(params.refractory_s / control_period_s))),
      arm_tolerance_s_(1e-6 * control_period_s) {
  assert(control_period_s > 0.0);
  assert(params.v_thr_mm_s > 0.0 && params.k_MPa_s_per_mm >= 0.0);
  assert(params.refractory_s >= 0.0 && params.arm_after_s >= 0.0);
}

double StretchReflex::update(double time_s, double velocity_m_s, bool may_trigger) {
  // idle: count down the refractory period, else look for a trigger
  triggered_ = false;
  if (window_left_ == 0) {
    active_ = false;
    if (refractory_left_ > 0) {
      --refractory_left_;
      return 0.0;
    }
    const bool armed = time_s + arm_tolerance_s_ >= arm_after_s_;
    if (!armed || !may_trigger || !(velocity_m_s > v_thr_m_s_)) return 0.0;
    // trigger: this tick is the first of the window
    triggered_ = true;
    v_latched_m_s_ = velocity_m_s;
    window_left_ = window_ticks_;
  }

  // active window: dp = k v, Eq. (14), with v followed (>= 0) or latched
  active_ = true;
  const double v = mode_ == ReflexMode::kLatch ? v_latched_m_s_
                 : (velocity_m_s > 0.0 ? velocity_m_s : 0.0);
  const double dp = k_pa_s_per_m_ * v;
  if (--window_left_ == 0) refractory_left_ = refractory_ticks_;
  return dp;
}

PairValues reflex_commands(const PairValues& p_tp_pa, const PairValues& dp_pa, double p_max_pa) {
  // Eq. (12)-(13): own excitation up, the other muscle's inhibition down; valve range
  PairValues p;
  p[kAgonist] = p_tp_pa[kAgonist] + dp_pa[kAgonist] - dp_pa[kAntagonist];
  p[kAntagonist] = p_tp_pa[kAntagonist] + dp_pa[kAntagonist] - dp_pa[kAgonist];
  for (double& pj : p) pj = std::clamp(pj, 0.0, p_max_pa);
  return p;
}

}  // namespace pamsim
