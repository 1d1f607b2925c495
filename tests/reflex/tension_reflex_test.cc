// tension_reflex_test.cc: the tension (Ib) reflex of one muscle (tension_reflex.h) against
// its definition: dp = k f in Pa from MPa/N, the window and refractory ticks, the trigger on
// the tension's level and, low-passed, on its rate at the tick the closed form gives, latch
// mode, a missing reading; the Ia + Ib command rule (reflex_commands) by hand; the
// controller with a silent Ib reflex commanding exactly what the Ia controller commands; a
// bad-value test for every validated key.
#include "reflex/tension_reflex.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "../sensing/sensing_test_util.h"

#include "reflex/stretch_reflex_controller.h"
#include "base/control_step.h"
#include "base/no_value.h"

namespace pamsim {
namespace {

using pamsim_test::kControlDt;

using test::expect_bad_value;

TensionReflexParams tension_params() {
  TensionReflexParams p;
  p.f_thr_N = 60.0;
  p.k_pa_per_n = 4000.0;  // 0.004 MPa/N
  p.duration_s = 0.05;    // 5 ticks
  p.refractory_s = 0.03;  // 3 ticks
  p.arm_after_s = 0.0;
  return p;
}

TEST(TensionReflexTest, ALevelOverTheThresholdOpensAWindowOfKTimesTheTension) {
  TensionReflex reflex(tension_params(), kControlDt);
  EXPECT_EQ(reflex.update(0.00, 59.0), 0.0);
  // 80 N: dp = 0.004 MPa/N * 80 N = 0.32 MPa, following the tension in the window
  const std::vector<double> tension = {80, 90, 50, 10, 70};
  for (std::size_t k = 0; k < tension.size(); ++k) {
    const double dp = reflex.update(0.01 * (k + 1), tension[k]);
    EXPECT_DOUBLE_EQ(dp, 0.004e6 * tension[k]) << "tick " << k;
    EXPECT_TRUE(reflex.active());
    EXPECT_EQ(reflex.triggered(), k == 0);
  }
  // the window is over: three refractory ticks at 100 N trigger nothing, the fourth does
  for (int k = 0; k < 3; ++k) EXPECT_EQ(reflex.update(0.06 + 0.01 * k, 100.0), 0.0) << k;
  EXPECT_DOUBLE_EQ(reflex.update(0.09, 100.0), 0.4e6);
  EXPECT_TRUE(reflex.triggered());
}

// A ramp of r N/s from 0 N stays under the level threshold; its backward difference is r
// from the second tick on, low-passed: after n >= 1 differences the rate reads
// r (1 - (1 - alpha)^n) (the filter starts at its first input, 0). The reflex triggers at the
// first tick that exceeds dF_thr, and never with dF_thr = 0.
TEST(TensionReflexTest, ARisingTensionTriggersOnItsRateAtTheTickTheClosedFormGives) {
  TensionReflexParams p = tension_params();
  p.df_thr_N_s = 600.0;
  p.rate_lowpass_hz = 10.0;
  const double r = 1000.0, alpha = 1.0 - std::exp(-2.0 * M_PI * 10.0 * kControlDt);
  int expected = -1;
  for (int n = 1; n < 50 && expected < 0; ++n) {
    if (r * (1.0 - std::pow(1.0 - alpha, n)) > 600.0) expected = n;
  }
  ASSERT_GT(expected, 1);
  TensionReflex rate(p, kControlDt);
  p.df_thr_N_s = 0.0;
  TensionReflex level_only(p, kControlDt);
  int fired = -1;
  for (int k = 0; k <= expected + 1; ++k) {
    const double f = r * kControlDt * k;  // 10 N a tick: under the 60 N level for these few ticks
    ASSERT_LT(f, 60.0);
    rate.update(k * kControlDt, f);
    level_only.update(k * kControlDt, f);
    if (rate.triggered() && fired < 0) fired = k;
    EXPECT_FALSE(level_only.triggered()) << k;
  }
  EXPECT_EQ(fired, expected);
  EXPECT_NEAR(rate.rate_n_s(), r * (1.0 - std::pow(1.0 - alpha, expected + 1)), 1e-9);
}

TEST(TensionReflexTest, LatchHoldsTheTriggeringTensionAndAMissingReadingTriggersNothing) {
  TensionReflexParams p = tension_params();
  p.mode = ReflexMode::kLatch;
  TensionReflex reflex(p, kControlDt);
  EXPECT_EQ(reflex.update(0.00, kNaN), 0.0);
  EXPECT_FALSE(reflex.triggered());
  EXPECT_DOUBLE_EQ(reflex.update(0.01, 75.0), 0.004e6 * 75.0);
  EXPECT_DOUBLE_EQ(reflex.update(0.02, 20.0), 0.004e6 * 75.0);
  const double rate = reflex.rate_n_s();
  ASSERT_TRUE(std::isfinite(rate));
  EXPECT_DOUBLE_EQ(reflex.update(0.03, kNaN), 0.004e6 * 75.0);
  EXPECT_EQ(reflex.rate_n_s(), rate) << "a NaN reading leaves the rate as it was";
}

TEST(TensionReflexTest, NotArmedNotTriggered) {
  TensionReflexParams p = tension_params();
  p.arm_after_s = 0.1;
  TensionReflex reflex(p, kControlDt);
  EXPECT_EQ(reflex.update(0.05, 200.0), 0.0);
  EXPECT_GT(reflex.update(0.10, 200.0), 0.0);
}

// p_ago = p_tp + dp_ia_ago - dp_ia_anta - dp_ib_ago + e dp_ib_anta, and symmetrically,
// clamped to [0, p_max]
TEST(TensionReflexTest, IaAndIbCommandsSumAsTheRuleSays) {
  const PairValues p_tp = {0.4e6, 0.3e6}, ia = {0.2e6, 0.05e6}, ib = {0.1e6, 0.02e6};
  const PairValues plain = reflex_commands(p_tp, ia, ib, false, 0.8e6);
  EXPECT_DOUBLE_EQ(plain[kAgonist], 0.4e6 + 0.2e6 - 0.05e6 - 0.1e6);
  EXPECT_DOUBLE_EQ(plain[kAntagonist], 0.3e6 + 0.05e6 - 0.2e6 - 0.02e6);
  const PairValues excited = reflex_commands(p_tp, ia, ib, true, 0.8e6);
  EXPECT_DOUBLE_EQ(excited[kAgonist], 0.4e6 + 0.2e6 - 0.05e6 - 0.1e6 + 0.02e6);
  EXPECT_DOUBLE_EQ(excited[kAntagonist], 0.3e6 + 0.05e6 - 0.2e6 - 0.02e6 + 0.1e6);
  const PairValues clamped = reflex_commands(p_tp, {0.6e6, 0.0}, {0.0, 0.5e6}, true, 0.8e6);
  EXPECT_EQ(clamped[kAgonist], 0.8e6);
  EXPECT_EQ(clamped[kAntagonist], 0.0);
  // no Ib output: Eq. (12)-(13) exactly
  EXPECT_EQ(reflex_commands(p_tp, ia, {0.0, 0.0}, true, 0.8e6), reflex_commands(p_tp, ia, 0.8e6));
}

// Readings that drive the Ia reflex but never reach the Ib threshold: the Ia + Ib controller
// commands bit for bit what the Ia controller commands, and records no Ib trigger.
TEST(TensionReflexTest, ASilentTensionReflexLeavesTheStretchReflexsCommands) {
  StretchReflexControllerConfig ia;
  ia.reflex.arm_after_s = 0.0;
  StretchReflexControllerConfig both = ia;
  both.tension = true;
  both.ib = tension_params();
  StretchReflexController a(ia), b(both);
  ASSERT_NE(b.tension_trigger_times_s(), nullptr);
  EXPECT_EQ(a.tension_trigger_times_s(), nullptr);
  std::vector<MuscleReading> readings(2);
  const std::vector<double> p_tp = {0.4e6, 0.4e6};
  ControlOutput out_a, out_b;
  out_a.resize(2, 1);
  out_b.resize(2, 2);
  for (int k = 0; k < 60; ++k) {
    readings[0].velocity_est_m_s = 0.15 * std::sin(0.3 * k);  // stretches past 70 mm/s
    readings[1].velocity_est_m_s = -0.1 * std::sin(0.3 * k);
    readings[0].force_meas_n = 30.0 + 25.0 * std::sin(0.2 * k);  // under 60 N
    readings[1].force_meas_n = 20.0;
    const ControlInput in{k * kControlDt, true, &readings, &p_tp};
    a.update(in, &out_a);
    b.update(in, &out_b);
    ASSERT_EQ(out_a.p_cmd_pa, out_b.p_cmd_pa) << "tick " << k;
  }
  EXPECT_GT(a.trigger_count(0), 0) << "the Ia reflex fired";
  EXPECT_TRUE((*b.tension_trigger_times_s())[0].empty());
}

TEST(TensionReflexTest, EveryValidatedKeyRefusesABadValue) {
  const auto bad = [](auto change, const char* key, const char* value) {
    TensionReflexParams p = tension_params();
    change(p);
    expect_bad_value([&] { validate(p, 100.0); }, key, value);
  };
  bad([](TensionReflexParams& p) { p.f_thr_N = -5.0; }, "reflex.ib.f_thr_N", "-5");
  bad([](TensionReflexParams& p) { p.f_thr_N = 0.0; }, "reflex.ib.f_thr_N", "0");
  bad([](TensionReflexParams& p) { p.df_thr_N_s = -1.0; }, "reflex.ib.df_thr_N_s", "-1");
  bad([](TensionReflexParams& p) { p.k_pa_per_n = kNaN; }, "reflex.ib.k_MPa_per_N", "nan");
  bad([](TensionReflexParams& p) { p.duration_s = 0.001; }, "reflex.ib.duration_s", "0.001");
  bad([](TensionReflexParams& p) { p.refractory_s = -0.1; }, "reflex.ib.refractory_s", "-0.1");
  bad([](TensionReflexParams& p) { p.arm_after_s = -1.0; }, "reflex.ib.arm_after_s", "-1");
  bad([](TensionReflexParams& p) { p.rate_lowpass_hz = 80.0; }, "reflex.ib.rate_lowpass_hz", "80");
}

}  // namespace
}  // namespace pamsim
