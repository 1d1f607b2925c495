// stretch_reflex_test.cc: trigger threshold, the 200 ms window, Eq. (12)-(14) with
// reciprocal inhibition and clamping, follow vs latch, refractory period and arming.
#include "reflex/stretch_reflex.h"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/input_error.h"
#include "base/control_step.h"

namespace pamsim {
namespace {

using pamsim_test::kControlDt;

StretchReflexParams params(double refractory_s = 10.0, double arm_after_s = 0.0) {
  StretchReflexParams p;  // 70 mm/s, k = 1/800 MPa per mm/s, 0.2 s, follow
  p.refractory_s = refractory_s;
  p.arm_after_s = arm_after_s;
  return p;
}

// A reflex and the times it triggered at, kept as StretchReflexController keeps them
// (StretchReflex::triggered after each update).
struct LoggedReflex {
  LoggedReflex(const StretchReflexParams& p, double dt) : reflex(p, dt) {}
  double update(double time_s, double velocity_m_s, bool may_trigger = true) {
    const double dp = reflex.update(time_s, velocity_m_s, may_trigger);
    if (reflex.triggered()) times.push_back(time_s);
    return dp;
  }
  bool active() const { return reflex.active(); }
  int trigger_count() const { return static_cast<int>(times.size()); }
  const std::vector<double>& trigger_times_s() const { return times; }
  StretchReflex reflex;
  std::vector<double> times;
};

// runs `n` ticks at constant velocity [mm/s]; returns dp [Pa] per tick
std::vector<double> run(LoggedReflex* reflex, int n, double v_mm_s, int* active_ticks,
                        int start_tick = 0) {
  std::vector<double> dp;
  for (int j = start_tick; j < start_tick + n; ++j) {
    dp.push_back(reflex->update(j * kControlDt, v_mm_s * 1e-3));
    if (reflex->active()) ++*active_ticks;
  }
  return dp;
}

TEST(StretchReflex, NoTriggerBelowOrAtThreshold) {
  LoggedReflex reflex(params(), kControlDt);
  int active = 0;
  for (double dp : run(&reflex, 100, 69.9, &active)) EXPECT_EQ(dp, 0.0);
  for (double dp : run(&reflex, 100, 70.0, &active, 100)) EXPECT_EQ(dp, 0.0);    // "exceeds"
  for (double dp : run(&reflex, 100, -500.0, &active, 200)) EXPECT_EQ(dp, 0.0);  // shortening
  EXPECT_EQ(active, 0);
  EXPECT_EQ(reflex.trigger_count(), 0);
}

TEST(StretchReflex, OneWindowOf200msAboveThreshold) {
  LoggedReflex reflex(params(), kControlDt);
  int active = 0;
  // stays above threshold for 1 s: the window is neither extended nor restarted
  const std::vector<double> dp = run(&reflex, 100, 100.0, &active);
  EXPECT_EQ(reflex.trigger_count(), 1);
  EXPECT_EQ(active, 20);
  // k v = 1/800 MPa per mm/s * 100 mm/s = 0.125 MPa
  for (int j = 0; j < 20; ++j) EXPECT_NEAR(dp[j], 0.125e6, 1e-6) << j;
  for (int j = 20; j < 100; ++j) EXPECT_EQ(dp[j], 0.0) << j;
  ASSERT_EQ(reflex.trigger_times_s().size(), 1u);
  EXPECT_DOUBLE_EQ(reflex.trigger_times_s()[0], 0.0);
}

TEST(StretchReflex, SingleSpikeGivesFullWindow) {
  StretchReflexParams p = params();
  p.mode = ReflexMode::kLatch;
  LoggedReflex reflex(p, kControlDt);
  int active = 0;
  run(&reflex, 5, 0.0, &active);
  run(&reflex, 1, 150.0, &active, 5);
  const std::vector<double> dp = run(&reflex, 40, 0.0, &active, 6);
  EXPECT_EQ(active, 20);
  EXPECT_EQ(reflex.trigger_count(), 1);
  EXPECT_DOUBLE_EQ(reflex.trigger_times_s()[0], 5 * kControlDt);
  EXPECT_NEAR(dp[18], 150.0 / 800.0 * 1e6, 1e-6);  // last tick of the window (tick 24)
  EXPECT_EQ(dp[19], 0.0);                          // tick 25: over
}

TEST(StretchReflex, FollowTracksVelocityLatchHoldsTrigger) {
  const double v_mm_s[] = {0.0, 100.0, 150.0, 80.0, 30.0, -20.0, 60.0};
  StretchReflexParams follow = params();
  StretchReflexParams latch = params();
  latch.mode = ReflexMode::kLatch;
  LoggedReflex rf(follow, kControlDt);
  LoggedReflex rl(latch, kControlDt);
  const double k_pa_per_mm_s = 1e6 / 800.0;
  for (int j = 0; j < 7; ++j) {
    const double df = rf.update(j * kControlDt, v_mm_s[j] * 1e-3);
    const double dl = rl.update(j * kControlDt, v_mm_s[j] * 1e-3);
    if (j == 0) {
      EXPECT_EQ(df, 0.0);
      EXPECT_EQ(dl, 0.0);
      continue;
    }
    EXPECT_NEAR(df, k_pa_per_mm_s * std::max(v_mm_s[j], 0.0), 1e-6) << j;  // clamped >= 0
    EXPECT_NEAR(dl, k_pa_per_mm_s * 100.0, 1e-6) << j;
    EXPECT_TRUE(rf.active());
    EXPECT_TRUE(rl.active());
  }
}

TEST(StretchReflex, RefractoryPeriodDelaysTheNextTrigger) {
  // constant stretch: windows of 20 ticks separated by 10 refractory ticks
  LoggedReflex reflex(params(0.1), kControlDt);
  int active = 0;
  run(&reflex, 100, 100.0, &active);
  ASSERT_EQ(reflex.trigger_count(), 4);  // ticks 0, 30, 60, 90
  EXPECT_NEAR(reflex.trigger_times_s()[1], 0.30, 1e-12);
  EXPECT_NEAR(reflex.trigger_times_s()[3], 0.90, 1e-12);
  // without a refractory period it re-fires at once
  LoggedReflex eager(params(0.0), kControlDt);
  active = 0;
  run(&eager, 100, 100.0, &active);
  EXPECT_EQ(eager.trigger_count(), 5);  // ticks 0, 20, 40, 60, 80
  EXPECT_EQ(active, 100);
  EXPECT_NEAR(eager.trigger_times_s()[1], 0.20, 1e-12);
}

TEST(StretchReflex, DisarmedUntilArmAfter) {
  LoggedReflex reflex(params(10.0, 0.5), kControlDt);
  int active = 0;
  const std::vector<double> dp = run(&reflex, 60, 200.0, &active);
  EXPECT_EQ(reflex.trigger_count(), 1);
  EXPECT_NEAR(reflex.trigger_times_s()[0], 0.5, 1e-12);
  EXPECT_EQ(dp[49], 0.0);
  EXPECT_GT(dp[50], 0.0);
}

TEST(StretchReflex, DurationRoundsToWholeTicks) {
  StretchReflexParams p = params();
  p.duration_s = 0.05;
  LoggedReflex reflex(p, kControlDt);
  int active = 0;
  run(&reflex, 50, 100.0, &active);
  EXPECT_EQ(active, 5);
}

TEST(ReflexCommands, ReciprocalInhibitionSigns) {
  // the agonist fires at 100 mm/s: agonist up by k v, antagonist down by k v, Eq. (12)-(13)
  LoggedReflex ago(params(), kControlDt);
  LoggedReflex anta(params(), kControlDt);
  const double dp_ago = ago.update(0.0, 0.100);
  const double dp_anta = anta.update(0.0, -0.100);
  const auto p = reflex_commands({0.4e6, 0.4e6}, {dp_ago, dp_anta}, 0.8e6);
  EXPECT_NEAR(p[kAgonist], 0.4e6 + 0.125e6, 1e-6);
  EXPECT_NEAR(p[kAntagonist], 0.4e6 - 0.125e6, 1e-6);
  // the antagonist firing does the opposite
  const auto q = reflex_commands({0.4e6, 0.3e6}, {0.0, 0.05e6}, 0.8e6);
  EXPECT_NEAR(q[kAgonist], 0.35e6, 1e-6);
  EXPECT_NEAR(q[kAntagonist], 0.35e6, 1e-6);
  // both: each gets its own excitation minus the other's inhibition
  const auto b = reflex_commands({0.4e6, 0.4e6}, {0.1e6, 0.03e6}, 0.8e6);
  EXPECT_NEAR(b[kAgonist], 0.47e6, 1e-6);
  EXPECT_NEAR(b[kAntagonist], 0.33e6, 1e-6);
}

TEST(ReflexCommands, ClampedToValveRange) {
  const auto p = reflex_commands({0.75e6, 0.05e6}, {0.125e6, 0.0}, 0.8e6);
  EXPECT_DOUBLE_EQ(p[kAgonist], 0.8e6);
  EXPECT_DOUBLE_EQ(p[kAntagonist], 0.0);
}

TEST(ReflexMode, ParsesAndRejectsNamingTheKey) {
  EXPECT_EQ(parse_reflex_mode("follow"), ReflexMode::kFollow);
  EXPECT_EQ(parse_reflex_mode("latch"), ReflexMode::kLatch);
  EXPECT_STREQ(to_string(ReflexMode::kLatch), "latch");
  try {
    parse_reflex_mode("hold");
    FAIL() << "no throw";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("reflex.mode"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("hold"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pamsim
