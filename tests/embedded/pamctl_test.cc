// pamctl_test.cc: the embedded controller's library (src/embedded/pamctl.h) against closed
// forms and its documented safe behaviour: the spring law's inversion against the quadratic
// formula, the low-pass's step response, the reflex window's ticks, Eq. (12)-(13) by hand,
// and every bad input (configuration fields, non-finite and out-of-range readings, a NaN
// command, an unconfigured state) with its flag.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "embedded/pamctl.h"

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Table IV's agonist, Eq. (3), in SI: f = (a3 p d + a2 p + a1 d + a0) d
pamctl_spring eq3_spring() {
  pamctl_spring s{};
  s.law = PAMCTL_LAW_EQ3;
  s.m_m_per_pa = 68.0e-3 / 1e6;
  s.h_m = 0.178;
  const double a[4] = {-0.91, 0.0053, 4.9, 0.071};  // N/mm, N/mm^2, N/(MPa mm), ...
  s.coef[0] = a[0] * 1e3;
  s.coef[1] = a[1] * 1e6;
  s.coef[2] = a[2] * 1e3 / 1e6;
  s.coef[3] = a[3] * 1e6 / 1e6;
  return s;
}

// a two-muscle reflex controller with valid settings
pamctl_config valid_config() {
  pamctl_config c{};
  c.muscle_count = 2;
  c.kind = PAMCTL_KIND_REFLEX;
  c.control_period_s = 0.01;
  c.pressure_alpha = 1.0;
  c.velocity_alpha = 1.0;
  c.p_max_pa = 0.8e6;
  c.reflex.enabled = c.reflex.stretch = true;
  c.reflex.sensor = PAMCTL_SENSOR_MODEL;
  c.reflex.min_tension_n = 1.0;
  c.reflex.ia = {0.07, 1.25e9, PAMCTL_MODE_FOLLOW, {20, 50, 0.1, 1e-8}};
  c.reflex.ib = {60.0, 0.0, 2000.0, PAMCTL_MODE_FOLLOW, 1.0, {20, 0, 0.1, 1e-8}};
  for (int j = 0; j < PAMCTL_MAX_MUSCLES; ++j) c.partner[j] = -1;
  c.partner[0] = 1;
  c.partner[1] = 0;
  for (int j = 0; j < 2; ++j) {
    pamctl_muscle_config& m = c.muscles[j];
    m.spring = eq3_spring();
    m.gauge_v_base_v = 0.0;
    m.gauge_q_v_per_n = 2.25e-3;
    m.pressure_zero_v = 1.0;
    m.pressure_v_per_mpa = 4.0;
    m.pressure_min_v = 0.0;
    m.pressure_max_v = 5.0;
    m.gauge_min_v = -5.0;
    m.gauge_max_v = 5.0;
  }
  return c;
}

TEST(Pamctl, Eq3InversionIsTheQuadraticFormulasPositiveRoot) {
  const pamctl_spring s = eq3_spring();
  for (double p : {0.1e6, 0.3e6, 0.6e6}) {
    for (double f : {5.0, 40.0, 120.0}) {
      double a[3];
      pamctl_spring_polynomial(&s, p, a);
      const double root = (-a[0] + std::sqrt(a[0] * a[0] + 4.0 * a[1] * f)) / (2.0 * a[1]);
      double d = -1.0;
      ASSERT_EQ(pamctl_invert_spring(&s, p, f, &d), PAMCTL_INVERSION_OK);
      EXPECT_NEAR(d, root, 1e-12) << p << " " << f;
    }
  }
  double d = 1.0;
  EXPECT_EQ(pamctl_invert_spring(&s, 0.3e6, 0.0, &d), PAMCTL_INVERSION_SLACK);
  EXPECT_EQ(d, 0.0);
  EXPECT_EQ(pamctl_invert_spring(&s, kNaN, 10.0, &d), PAMCTL_INVERSION_NO_ROOT);
  EXPECT_EQ(d, 0.0);
}

TEST(Pamctl, CubicRootsOfAKnownPolynomial) {
  // (x - 1)(x - 2)(x - 3) = x^3 - 6 x^2 + 11 x - 6: the smallest positive root is 1
  EXPECT_NEAR(pamctl_smallest_positive_root(1.0, -6.0, 11.0, 6.0), 1.0, 1e-14);
  EXPECT_LT(pamctl_smallest_positive_root(-1.0, 0.0, -1.0, 1.0), 0.0);  // none
  EXPECT_LT(pamctl_smallest_positive_root(1.0, 0.0, 0.0, kInf), 0.0);
}

TEST(Pamctl, LowpassStepResponseIsTheExactFirstOrderOne) {
  const double alpha = 1.0 - std::exp(-2.0 * M_PI * 5.0 * 0.01);
  pamctl_lowpass f;
  pamctl_lowpass_init(&f, alpha);
  EXPECT_EQ(pamctl_lowpass_step(&f, 0.0), 0.0);  // starts at its first input
  double y = 0.0;
  for (int n = 1; n <= 10; ++n) y = pamctl_lowpass_step(&f, 1.0);
  EXPECT_NEAR(y, 1.0 - std::pow(1.0 - alpha, 10), 1e-15);
}

TEST(Pamctl, WindowOpensForItsTicksThenIsRefractory) {
  const pamctl_window_config c = {3, 2, 0.05, 1e-8};
  pamctl_window w{};
  std::vector<int> open;
  for (int k = 0; k < 12; ++k) open.push_back(pamctl_window_update(&c, &w, k * 0.01, true));
  // disarmed until 0.05 s, then 3 open, 2 refractory, 3 open again, 1 refractory
  EXPECT_EQ(open, (std::vector<int>{0, 0, 0, 0, 0, 1, 1, 1, 0, 0, 1, 1}));
}

TEST(Pamctl, PairCommandsAreEq12And13ByHandAndClamped) {
  pamctl_reflex_config rc{};
  const double p_tp[2] = {0.4e6, 0.3e6}, ia[2] = {0.1e6, 0.02e6}, ib[2] = {0.05e6, 0.01e6};
  EXPECT_EQ(pamctl_pair_command(&rc, p_tp, ia, ib, 0, 1), 0.4e6 + 0.1e6 - 0.02e6);
  rc.tension = rc.excite_antagonist = true;
  EXPECT_EQ(pamctl_pair_command(&rc, p_tp, ia, ib, 1, 0), 0.3e6 + 0.02e6 - 0.1e6 - 0.01e6 + 0.05e6);
  std::uint32_t flags = 0;
  EXPECT_EQ(pamctl_valve_command(0.9e6, 0.8e6, &flags), 0.8e6);
  EXPECT_EQ(pamctl_valve_command(-1.0, 0.8e6, &flags), 0.0);
  EXPECT_EQ(flags, 0u);
  EXPECT_EQ(pamctl_valve_command(kNaN, 0.8e6, &flags), 0.0);  // std::clamp passed it through
  EXPECT_EQ(flags, PAMCTL_FLAG_COMMAND_VENTED);
}

// one tick of a valid controller with the gauge at `gauge_v` and the pressures at 0.4 MPa
pamctl_output tick_with(pamctl_state* state, const pamctl_config& c, double pressure_v,
                        double gauge_v, double fiber, double p_tp) {
  pamctl_input in{};
  in.enabled = true;
  for (int j = 0; j < 2; ++j) {
    in.pressure_v[j] = pressure_v;
    in.gauge_v[j] = gauge_v;
    in.fiber_rate_m_s[j] = fiber;
    in.p_tp_pa[j] = p_tp;
  }
  pamctl_output out{};
  pamctl_tick(&c, state, &in, &out);
  return out;
}

TEST(Pamctl, MissingReadingsHoldTheEstimateAndAreFlagged) {
  const pamctl_config c = valid_config();
  pamctl_state s{};
  ASSERT_EQ(pamctl_init(&c, &s), 0);
  const pamctl_output first = tick_with(&s, c, 2.6, 0.1, 0.0, 0.4e6);
  EXPECT_EQ(first.status, 0u);
  for (double bad : {kNaN, kInf, -kInf}) {
    const pamctl_output held = tick_with(&s, c, bad, 0.1, 0.0, 0.4e6);
    EXPECT_EQ(held.estimates[0].length_m, first.estimates[0].length_m);
    EXPECT_EQ(held.estimates[0].velocity_m_s, 0.0);
    EXPECT_TRUE(held.status & PAMCTL_FLAG_NONFINITE_READING);
    EXPECT_EQ(held.p_cmd_pa[0], 0.4e6);  // the schedule, no reflex
    const pamctl_output no_gauge = tick_with(&s, c, 2.6, bad, 0.0, 0.4e6);
    EXPECT_TRUE(std::isnan(no_gauge.estimates[0].force_n) ||
                std::isinf(no_gauge.estimates[0].force_n));
    EXPECT_TRUE(no_gauge.status & PAMCTL_FLAG_NONFINITE_READING);
    const pamctl_output no_fiber = tick_with(&s, c, 2.6, 0.1, bad, 0.4e6);
    EXPECT_EQ(no_fiber.estimates[0].fiber_velocity_m_s, 0.0);
    EXPECT_TRUE(no_fiber.status & PAMCTL_FLAG_NONFINITE_READING);
  }
  // a fiber filter that was fed no NaN still reads finite afterwards
  EXPECT_TRUE(
      std::isfinite(tick_with(&s, c, 2.6, 0.1, 0.01, 0.4e6).estimates[0].fiber_velocity_m_s));
}

TEST(Pamctl, AfterAGapTheVelocitySpansTheWholeGap) {
  // the length change over the missing ticks is one rate over their span, not a jump in one
  const pamctl_config c = valid_config();
  pamctl_state s{};
  ASSERT_EQ(pamctl_init(&c, &s), 0);
  const double before = tick_with(&s, c, 2.6, 0.1, 0.0, 0.4e6).estimates[0].length_m;
  tick_with(&s, c, kNaN, 0.1, 0.0, 0.4e6);
  tick_with(&s, c, kNaN, 0.1, 0.0, 0.4e6);
  const pamctl_estimate after = tick_with(&s, c, 2.6, 0.3, 0.0, 0.4e6).estimates[0];
  EXPECT_NEAR(after.velocity_m_s, (after.length_m - before) / (3 * 0.01), 1e-12);
  EXPECT_EQ(after.flags, 0u);
}

TEST(Pamctl, OutOfRangeReadingsAreUsedAndFlagged) {
  const pamctl_config c = valid_config();
  pamctl_state s{};
  ASSERT_EQ(pamctl_init(&c, &s), 0);
  const pamctl_output out = tick_with(&s, c, 5.5, 0.1, 0.0, 0.4e6);
  EXPECT_TRUE(out.status & PAMCTL_FLAG_READING_OUT_OF_RANGE);
  EXPECT_EQ(out.estimates[0].pressure_pa, (5.5 - 1.0) / 4.0 * 1e6);
}

TEST(Pamctl, ANaNGoalPressureVentsThatValve) {
  const pamctl_config c = valid_config();
  pamctl_state s{};
  ASSERT_EQ(pamctl_init(&c, &s), 0);
  const pamctl_output out = tick_with(&s, c, 2.6, 0.1, 0.0, kNaN);
  EXPECT_EQ(out.p_cmd_pa[0], 0.0);
  EXPECT_EQ(out.p_cmd_pa[1], 0.0);
  EXPECT_TRUE(out.status & PAMCTL_FLAG_COMMAND_VENTED);
}

TEST(Pamctl, AnUnconfiguredControllerVentsEveryValve) {
  pamctl_config c = valid_config();
  c.control_period_s = -1.0;
  pamctl_state s{};
  EXPECT_NE(pamctl_init(&c, &s), 0);
  const pamctl_output out = tick_with(&s, c, 2.6, 0.1, 0.0, 0.4e6);
  EXPECT_EQ(out.status, PAMCTL_STATUS_UNCONFIGURED);
  for (int j = 0; j < PAMCTL_MAX_MUSCLES; ++j) EXPECT_EQ(out.p_cmd_pa[j], 0.0);
}

TEST(Pamctl, EveryBadConfigurationFieldIsRefusedWithItsName) {
  // each mutation breaks one checked field; the code names it
  const std::vector<std::pair<const char*, std::function<void(pamctl_config*)>>> bad = {
      {"muscle_count", [](pamctl_config* c) { c->muscle_count = PAMCTL_MAX_MUSCLES + 1; }},
      {"muscle_count", [](pamctl_config* c) { c->muscle_count = -1; }},
      {"kind", [](pamctl_config* c) { c->kind = 7; }},
      {"control_period_s", [](pamctl_config* c) { c->control_period_s = kNaN; }},
      {"pressure_alpha", [](pamctl_config* c) { c->pressure_alpha = 0.0; }},
      {"velocity_alpha", [](pamctl_config* c) { c->velocity_alpha = 1.5; }},
      {"p_max_pa", [](pamctl_config* c) { c->p_max_pa = 0.0; }},
      {"reflex.sensor", [](pamctl_config* c) { c->reflex.sensor = 3; }},
      {"reflex.ia.v_thr_m_s", [](pamctl_config* c) { c->reflex.ia.v_thr_m_s = 0.0; }},
      {"reflex.ia.k_pa_s_per_m", [](pamctl_config* c) { c->reflex.ia.k_pa_s_per_m = -1.0; }},
      {"reflex.ia.mode", [](pamctl_config* c) { c->reflex.ia.mode = 2; }},
      {"reflex.ib.f_thr_n", [](pamctl_config* c) { c->reflex.ib.f_thr_n = kInf; }},
      {"reflex.ib.df_thr_n_s", [](pamctl_config* c) { c->reflex.ib.df_thr_n_s = -1.0; }},
      {"reflex.ib.k_pa_per_n", [](pamctl_config* c) { c->reflex.ib.k_pa_per_n = kNaN; }},
      {"reflex.ib.mode", [](pamctl_config* c) { c->reflex.ib.mode = -1; }},
      {"reflex.ib.rate_alpha", [](pamctl_config* c) { c->reflex.ib.rate_alpha = 0.0; }},
      {"window", [](pamctl_config* c) { c->reflex.ia.window.window_ticks = 0; }},
      {"window", [](pamctl_config* c) { c->reflex.ib.window.refractory_ticks = -1; }},
      {"window", [](pamctl_config* c) { c->reflex.ia.window.arm_after_s = -0.1; }},
      {"min_tension_n", [](pamctl_config* c) { c->reflex.min_tension_n = kNaN; }},
      {"partner", [](pamctl_config* c) { c->partner[1] = 1; }},
      {"partner", [](pamctl_config* c) { c->partner[0] = 5; }},
      {"spring.law", [](pamctl_config* c) { c->muscles[0].spring.law = 6; }},
      {"spring's", [](pamctl_config* c) { c->muscles[1].spring.coef[2] = kInf; }},
      {"gauge_q_v_per_n", [](pamctl_config* c) { c->muscles[0].gauge_q_v_per_n = 0.0; }},
      {"pressure_v_per_mpa", [](pamctl_config* c) { c->muscles[0].pressure_v_per_mpa = -4.0; }},
      {"sensor ranges", [](pamctl_config* c) { c->muscles[1].gauge_max_v = -6.0; }},
  };
  pamctl_config good = valid_config();
  ASSERT_EQ(pamctl_check_config(&good), 0) << pamctl_config_error(pamctl_check_config(&good));
  for (const auto& [name, mutate] : bad) {
    pamctl_config c = valid_config();
    mutate(&c);
    const std::int32_t code = pamctl_check_config(&c);
    ASSERT_NE(code, 0) << name;
    EXPECT_NE(std::string(pamctl_config_error(code)).find(name), std::string::npos)
        << name << ": " << pamctl_config_error(code);
  }
  EXPECT_EQ(std::string(pamctl_config_error(999)), "unknown configuration error");
}

}  // namespace
