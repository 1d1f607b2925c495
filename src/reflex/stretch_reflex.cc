// stretch_reflex.cc: trigger, window, refractory and arming of one muscle's reflex;
// Eq. (12)-(14).
#include "reflex/stretch_reflex.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

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

pamctl_window_config embedded_window(double duration_s, double refractory_s, double arm_after_s,
                                     double control_period_s) {
  assert(control_period_s > 0.0);
  assert(refractory_s >= 0.0 && arm_after_s >= 0.0);
  pamctl_window_config window{};
  window.window_ticks = std::max(1, static_cast<int>(std::lround(duration_s / control_period_s)));
  window.refractory_ticks = static_cast<int>(std::lround(refractory_s / control_period_s));
  window.arm_after_s = arm_after_s;
  window.arm_tolerance_s = 1e-6 * control_period_s;
  return window;
}

ReflexWindow::ReflexWindow(double duration_s, double refractory_s, double arm_after_s,
                           double control_period_s)
    : config_(embedded_window(duration_s, refractory_s, arm_after_s, control_period_s)) {}

bool ReflexWindow::update(double time_s, bool trigger) {
  return pamctl_window_update(&config_, &window_, time_s, trigger);
}

pamctl_stretch_config embedded_stretch(const StretchReflexParams& params, double control_period_s) {
  pamctl_stretch_config config{};
  config.v_thr_m_s = params.v_thr_m_s;
  config.k_pa_s_per_m = params.k_pa_s_per_m;
  config.mode = params.mode == ReflexMode::kLatch ? PAMCTL_MODE_LATCH : PAMCTL_MODE_FOLLOW;
  config.window =
      embedded_window(params.duration_s, params.refractory_s, params.arm_after_s, control_period_s);
  return config;
}

StretchReflex::StretchReflex(const StretchReflexParams& params, double control_period_s)
    : config_(embedded_stretch(params, control_period_s)) {
  assert(params.v_thr_m_s > 0.0 && params.k_pa_s_per_m >= 0.0);
}

double StretchReflex::update(double time_s, double velocity_m_s, bool may_trigger) {
  // Eq. (14) in the embedded controller's code
  return pamctl_stretch_update(&config_, &state_, time_s, velocity_m_s, may_trigger);
}

PairValues reflex_commands(const PairValues& p_tp_pa, const PairValues& dp_pa, double p_max_pa) {
  // Eq. (12)-(13) in the embedded controller's code: own excitation up, the other muscle's
  // inhibition down; the valve's range
  pamctl_reflex_config rc{};
  const double no_ib[2] = {0.0, 0.0};
  PairValues p;
  std::uint32_t flags = 0;
  for (int j : {kAgonist, kAntagonist}) {
    const double pj = pamctl_pair_command(&rc, p_tp_pa.data(), dp_pa.data(), no_ib, j, 1 - j);
    p[j] = pamctl_valve_command(pj, p_max_pa, &flags);
  }
  return p;
}

}  // namespace pamsim
