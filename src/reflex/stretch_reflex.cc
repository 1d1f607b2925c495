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

ReflexMode parse_reflex_mode(const std::string& name, const std::string& key) {
  return parse_name(kModeNames, name, key);
}

ReflexWindow::ReflexWindow(double duration_s, double refractory_s, double arm_after_s,
                           double control_period_s)
    : arm_after_s_(arm_after_s),
      window_ticks_(std::max(1, static_cast<int>(std::lround(duration_s / control_period_s)))),
      refractory_ticks_(static_cast<int>(std::lround(refractory_s / control_period_s))),
      arm_tolerance_s_(1e-6 * control_period_s) {
  assert(control_period_s > 0.0);
  assert(refractory_s >= 0.0 && arm_after_s >= 0.0);
}

bool ReflexWindow::update(double time_s, bool trigger) {
  // idle: count down the refractory period, else look for a trigger
  triggered_ = false;
  if (window_left_ == 0) {
    active_ = false;
    if (refractory_left_ > 0) {
      --refractory_left_;
      return false;
    }
    const bool armed = time_s + arm_tolerance_s_ >= arm_after_s_;
    if (!armed || !trigger) return false;
    // trigger: this tick is the first of the window
    triggered_ = true;
    window_left_ = window_ticks_;
  }
  active_ = true;
  if (--window_left_ == 0) refractory_left_ = refractory_ticks_;
  return true;
}

StretchReflex::StretchReflex(const StretchReflexParams& params, double control_period_s)
    : v_thr_m_s_(params.v_thr_m_s),
      k_pa_s_per_m_(params.k_pa_s_per_m),
      mode_(params.mode),
      window_(params.duration_s, params.refractory_s, params.arm_after_s, control_period_s) {
  assert(params.v_thr_m_s > 0.0 && params.k_pa_s_per_m >= 0.0);
}

double StretchReflex::update(double time_s, double velocity_m_s, bool may_trigger) {
  if (!window_.update(time_s, may_trigger && velocity_m_s > v_thr_m_s_)) return 0.0;
  if (window_.triggered()) v_latched_m_s_ = velocity_m_s;
  // active window: dp = k v, Eq. (14), with v followed (>= 0) or latched
  const double v = mode_ == ReflexMode::kLatch ? v_latched_m_s_
                 : (velocity_m_s > 0.0 ? velocity_m_s : 0.0);
  return k_pa_s_per_m_ * v;
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
