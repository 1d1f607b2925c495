// leg_test.cc: the PAM leg (models/leg_pam.xml) through its scenarios, with no leg-specific
// code: each line starts its muscle 2 mm past the plant's free length at 0.4 MPa (`pamsim
// calibrate --pose`: pose_calibration_test.cc), the leg falls 100 mm, lands (the floor's push
// peaks above its weight), bounces and stands crouched; dropped from higher it collapses
// further; the start keys place it; it hops periodically under its feedforward pattern, with
// and without its reflexes; each tendon crosses the joints its muscle says it spans (RF and
// GAS two); and its scenarios refuse bad input by key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/units.h"
#include "pam_actuator/avbdl.h"
#include "sim/core/calibration.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "sim/optimize/tuning_file.h"
#include "sim/sweep/sweep.h"
#include "sim/scenario_errors.h"

namespace pamsim {
namespace {

using pamsim_test::kScenarios;
constexpr double kLegMass_kg = 1.016 + 0.30 + 0.14 + 0.044;  // trunk, thigh, shank, foot

TrialResult land(const std::vector<std::string>& overrides = {}) {
  const Scenario sc = load_scenario(kScenarios + "landing.toml", overrides);
  const TrialModel model = load_trial_model(sc);
  return run_trial(model, sc, sc.seed);
}

TEST(LegTest, EachLineStartsItsMuscleTwoMillimetresPastItsFreeLength) {
  const Scenario sc = load_scenario(kScenarios + "landing.toml", {"sim.duration_s=0.01"});
  const TrialModel model = load_trial_model(sc);
  const TrialResult r = run_trial(model, sc, sc.seed);
  ASSERT_EQ(sc.muscles.size(), 8u);
  for (const MuscleSpec& m : sc.muscles) {
    SCOPED_TRACE(m.key);
    const double start_mm = r.trajectory.at(0, r.trajectory.column("length_" + m.label + "_mm"));
    const double free_mm = units::m_to_mm(avbdl_free_length(m.plant, 0.4e6));
    // the script reads the free length off the tensile CSV (its encoder's 0.01 mm noise)
    EXPECT_NEAR(start_mm, free_mm + 2.0, 0.05);
  }
}

TEST(LegTest, TheLegLandsBouncesAndStandsCrouched) {
  const TrialResult r = land();
  ASSERT_EQ(r.summary.status, "ok") << r.summary.message;
  const double weight_n = kLegMass_kg * 9.81;
  EXPECT_GT(r.summary.metric("grf_max_N"), 3.0 * weight_n) << "an impact, not a touch";
  EXPECT_GE(r.summary.metric("grf_touchdowns"), 2.0) << "it bounces";
  EXPECT_NEAR(r.summary.metric("trunk_z_max_mm"), 475.0 + 93.3, 0.1) << "it starts 100 mm up";
  // it stands at the end, crouched near its start, not collapsed onto its knee's limit
  EXPECT_NEAR(r.summary.metric("angle_final_deg"), 20.0, 5.0);
  EXPECT_LT(r.summary.metric("knee_angle_max_deg"), 60.0);
  EXPECT_GT(r.summary.metric("trunk_z_min_mm"), 400.0);
}

TEST(LegTest, AHigherDropCollapsesTheKneeFurtherAndPushesHarder) {
  const TrialResult low = land({"joints.trunk_z.start_mm=43.3"});
  const TrialResult high = land({"joints.trunk_z.start_mm=193.3"});
  EXPECT_GT(high.summary.metric("knee_angle_max_deg"), low.summary.metric("knee_angle_max_deg"));
  EXPECT_GT(high.summary.metric("grf_max_N"), low.summary.metric("grf_max_N"));
  EXPECT_GT(high.summary.metric("peak_tension_VAS_N"), low.summary.metric("peak_tension_VAS_N"));
}

// With its antigravity muscles at 0.1 MPa the leg cannot hold its weight: the "fall" event
// (the trunk below 0.40 m) ends the trial and the metric set "events" says when; the shipped
// landing does not fall
TEST(LegTest, AWeakLegFallsAndTheFallEventSaysWhen) {
  const TrialResult standing = land();
  EXPECT_TRUE(standing.summary.message.empty()) << standing.summary.message;
  EXPECT_TRUE(std::any_of(standing.summary.metrics.begin(), standing.summary.metrics.end(),
                          [](const Metric& m) { return m.name == "event_fall_time_s"; }));
  EXPECT_TRUE(std::isnan(standing.summary.metric("event_fall_time_s")));
  std::vector<std::string> weak;
  for (const char* m : {"GM", "VAS", "SOL"}) {
    weak.push_back(std::string("muscles.") + m + ".command={kind=\"constant\", MPa=0.1}");
  }
  const TrialResult r = land(weak);
  ASSERT_EQ(r.summary.status, "ok");
  const double fall = r.summary.metric("event_fall_time_s");
  EXPECT_GT(fall, 0.143) << "after the landing (a 100 mm free fall takes 0.143 s)";
  EXPECT_LT(fall, 1.0);
  EXPECT_EQ(r.summary.message, "ended by event fall");
}

// `pamsim calibrate` balances its joint with the model's other joints at their start keys
// (it had left them at 0): the knee holds the shank and foot, whose lever turns with the
// thigh, so the hip's start changes the knee's gravity torque
double knee_gravity_torque_nm(const std::vector<std::string>& overrides) {
  const Scenario sc = load_scenario(kScenarios + "landing.toml", overrides);
  const TrialModel model = load_trial_model(sc);
  CalibrationRequest req;
  req.start_angle_rad = units::deg_to_rad(20.0);
  req.pressure_agonist_pa = req.pressure_antagonist_pa = 0.4e6;
  req.antagonist_deformation_m = 0.002;
  ReflexPair knee;
  knee.agonist = model.muscle_index(sc, "VAS");
  knee.antagonist = model.muscle_index(sc, "BFS");
  return solve_calibration(model, sc, knee, req).gravity_torque_nm;
}

TEST(LegTest, CalibrationPlacesTheOtherJointsAtTheirStartKeys) {
  const double flexed = knee_gravity_torque_nm({"joints.hip.start_deg=60"});
  const double crouched = knee_gravity_torque_nm({});  // hip 10
  const double straight = knee_gravity_torque_nm({"joints.hip.start_deg=0"});
  EXPECT_GT(std::fabs(flexed - crouched), 0.1 * std::fabs(crouched));
  EXPECT_NE(crouched, straight);
}

// Ia + Ib might be expected to collapse the knee less than no reflex at the shipped height.
// Behind the shipped ITV1000-class regulator (Mowgli 2's kind of valve: proportional
// pressure-control valves on the robot) that is physically false: the impact is over about
// 25 ms after touchdown, inside the regulator's 10 ms dead time and 20 ms lag, so on every
// seed the collapse and the floor's push are the same with and without the reflexes (to 0.1
// deg and 1 N), while the Ia reflex does act on what follows (fewer bounces over five
// seeds: a single seed's count can flip). The Ib reflex is silent on this landing (its
// threshold is above the 100 mm landing's pulls). This test pins that finding; the next one
// the direct valve's, where the reflexes can act within the impact.
TEST(LegTest, BehindTheShippedRegulatorTheReflexesActOnlyAfterTheImpact) {
  const Scenario on = load_scenario(kScenarios + "landing_reflex.toml");
  const Scenario off = load_scenario(kScenarios + "landing_reflex.toml", {"reflex.enabled=false"});
  const TrialModel model = load_trial_model(on);
  double touchdowns_on = 0.0, touchdowns_off = 0.0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const TrialSummary with = run_trial(model, on, seed).summary;
    const TrialSummary without = run_trial(model, off, seed).summary;
    ASSERT_GT(with.metric("reflex_triggers_VAS"), 0.0) << "the Ia reflex fires, seed " << seed;
    EXPECT_NEAR(with.metric("knee_angle_max_deg"), without.metric("knee_angle_max_deg"), 0.1);
    EXPECT_NEAR(with.metric("grf_max_N"), without.metric("grf_max_N"), 1.0);
    touchdowns_on += with.metric("grf_touchdowns");
    touchdowns_off += without.metric("grf_touchdowns");
  }
  EXPECT_LT(touchdowns_on, touchdowns_off);
}

// Behind a direct valve, with the gains scenarios/sweep_landing_gains.toml finds (Ia 0.00094,
// Ib 0.0034), Ia + Ib collapses the knee less than no reflex on the 100 mm landing (29.45 deg
// against 30.7 over seeds 1-20, every one below; on seeds 1001-1020 two of 20 collapse more,
// docs/tension-reflex.md), where the Ia reflex alone collapses it more (37.4): the Ib reflex takes
// back the Ia reflex's push on the rebound. Behind the shipped regulator no reflex changes the
// collapse (docs/leg.md).
TEST(LegTest, BehindADirectValveIaAndIbCollapseTheKneeLessThanNoReflex) {
  const auto collapse = [](const std::vector<std::string>& sets) {
    std::vector<std::string> all = {"valve.model=\"iso6358\""};
    all.insert(all.end(), sets.begin(), sets.end());
    const Scenario sc = load_scenario(kScenarios + "landing_reflex.toml", all);
    const TrialModel model = load_trial_model(sc);
    return run_trial(model, sc, sc.seed).summary.metric("knee_angle_max_deg");
  };
  const double none = collapse({"reflex.enabled=false"});
  const double ia = collapse({"reflex.k_MPa_s_per_mm=0.00094", "reflex.ib.k_MPa_per_N=0"});
  const double both = collapse({"reflex.k_MPa_s_per_mm=0.00094", "reflex.ib.k_MPa_per_N=0.0034"});
  EXPECT_LT(both, none);
  EXPECT_GT(ia, none + 3.0);
}

TEST(LegTest, TheGainSweepIsAGridBehindADirectValve) {
  const SweepDefinition sweep = load_sweep(kScenarios + "sweep_landing_gains.toml");
  EXPECT_EQ(sweep.trials(), 8 * 8 * 2);
  ASSERT_EQ(sweep.axes.size(), 2u);
  EXPECT_EQ(sweep.axes[0].key, "reflex.k_MPa_s_per_mm");
  EXPECT_EQ(sweep.fixed, std::vector<std::string>{"valve.model='iso6358'"});
}

TEST(LegTest, TheGainTuningReadsBehindADirectValve) {
  const TuneDefinition tune = load_tune_definition(kScenarios + "tune_landing.toml");
  ASSERT_EQ(tune.parameters.size(), 2u);
  EXPECT_EQ(tune.parameters[1].key, "reflex.ib.k_MPa_per_N");
  EXPECT_EQ(tune.overrides, std::vector<std::string>{"valve.model=\"iso6358\""});
}

// The reflex scenario with its reflexes off is the reflex-free landing, bit for bit
TEST(LegTest, TheReflexLandingWithItsReflexesOffIsThePassiveOne) {
  const Scenario sc = load_scenario(kScenarios + "landing_reflex.toml", {"reflex.enabled=false"});
  const TrialModel model = load_trial_model(sc);
  const TrialResult off = run_trial(model, sc, sc.seed);
  const TrialResult none = land();
  EXPECT_EQ(off.summary.metric("knee_angle_max_deg"), none.summary.metric("knee_angle_max_deg"));
  EXPECT_EQ(off.summary.metric("grf_max_N"), none.summary.metric("grf_max_N"));
}

// The trunk's apexes above 0 mm (the straight leg's height with the sole on the floor: the
// foot is in the air), one per hop
std::vector<double> hop_apexes_mm(const TrialResult& r) {
  const Trajectory& log = r.trajectory;
  const std::size_t z = log.column("position_mm");
  std::vector<double> apexes;
  for (std::size_t row = 1; row + 1 < log.rows(); ++row) {
    const double here = log.at(row, z);
    if (here > 0.0 && here > log.at(row - 1, z) && here >= log.at(row + 1, z)) {
      apexes.push_back(here);
    }
  }
  return apexes;
}

TrialResult hop(const std::vector<std::string>& overrides) {
  const Scenario sc = load_scenario(kScenarios + "hopping.toml", overrides);
  const TrialModel model = load_trial_model(sc);
  return run_trial(model, sc, sc.seed);
}

// Without reflexes the pattern hops 11 times in 5 s, every hop after the first to the same
// height within 2 %; with the reflexes on it still hops at least five times, each within
// 30 % of the median hop (the Ia reflex, firing on some landings, perturbs the rhythm)
TEST(LegTest, TheLegHopsPeriodically) {
  const std::vector<double> plain = hop_apexes_mm(hop({"reflex.enabled=false"}));
  ASSERT_GE(plain.size(), 5u);
  for (std::size_t k = 1; k < plain.size(); ++k) EXPECT_NEAR(plain[k], plain[1], 0.02 * plain[1]);
  EXPECT_GT(plain[1], 10.0) << "hops of centimetres, not a shuffle";
  const TrialResult reflexes = hop({});
  ASSERT_EQ(reflexes.summary.status, "ok");
  std::vector<double> apexes = hop_apexes_mm(reflexes);
  ASSERT_GE(apexes.size(), 5u);
  std::vector<double> sorted = apexes;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (double apex : apexes) EXPECT_NEAR(apex, median, 0.3 * median);
  EXPECT_GE(reflexes.summary.metric("grf_touchdowns"), 5.0);
}

// From its deep crouch, held at 0.17 MPa, the push-off lifts the straight leg's sole clear of
// the floor by more than 50 mm (96 mm without reflexes), with or without the reflexes, and it
// lands without falling
TEST(LegTest, TheSquatJumpLeavesTheFloor) {
  for (const char* reflexes : {"reflex.enabled=false", "reflex.enabled=true"}) {
    SCOPED_TRACE(reflexes);
    const Scenario sc = load_scenario(kScenarios + "squat_jump.toml", {reflexes});
    const TrialModel model = load_trial_model(sc);
    const TrialResult r = run_trial(model, sc, sc.seed);
    ASSERT_EQ(r.summary.status, "ok") << r.summary.message;
    EXPECT_NEAR(r.summary.metric("position_start_mm"), -58.9, 0.1) << "the deep crouch";
    EXPECT_GT(r.summary.metric("trunk_z_max_mm") - 475.0, 50.0);
    EXPECT_GE(r.summary.metric("grf_touchdowns"), 1.0);
    EXPECT_NE(r.summary.message, "ended by event fall");
    EXPECT_EQ(r.summary.metric("sim_time_s"), sc.duration_s) << "it ran to the end";
    // the push-off straightens the knee onto its stop, which gives 5.2-5.7 deg (MuJoCo's
    // default soft limit gave 11.5)
    EXPECT_LT(r.summary.metric("knee_angle_min_deg"), 0.0) << "it reaches the stop";
    EXPECT_GT(r.summary.metric("knee_angle_min_deg"), -7.0) << "and the stop holds";
  }
}

// What binding checks (a tendon's spans, the metric names against the model's sensors) is
// part of the trial model: a sweep point that changes only those is bound, and checked, anew
TEST(LegTest, SpansAndMetricSetsAreOfTheTrialModel) {
  const Scenario base = load_scenario(kScenarios + "landing.toml");
  EXPECT_TRUE(same_trial_model(base, load_scenario(kScenarios + "landing.toml")));
  EXPECT_FALSE(same_trial_model(
      base, load_scenario(kScenarios + "landing.toml", {"muscles.RF.spans=[\"hip\"]"})));
  EXPECT_FALSE(same_trial_model(
      base, load_scenario(kScenarios + "landing.toml", {"metrics=[\"tracking\"]"})));
}

TEST(LegTest, BadLegInputIsOneLineNamingTheKey) {
  pamsim_test::expect_each_named(
      "landing.toml",
      {{{"joints.knee.start_deg=720"}, "joints.knee.start_deg"},
       {{"joints.trunk_z.start_deg=10"}, "joints.trunk_z"},  // a slide
       {{"joints.knee.start_deg=-10"}, "joints.knee.start_deg must be within the joint's range"},
       {{"muscles.VAS.line_mm=0"}, "muscles.VAS.line_mm"},
       // a biarticular tendon whose path misses a joint it is said to cross
       {{"muscles.RF.spans=[\"hip\", \"ankle\"]"},
        "muscles.RF.spans names joint 'ankle', which the tendon's path misses"},
       {{"muscles.GAS.spans=[\"knee\", \"elbow\"]"}, "muscles.GAS.spans"}});
  pamsim_test::expect_each_named(
      "landing_reflex.toml",
      {{{"reflex.ib.f_thr_N=-1"}, "reflex.ib.f_thr_N"},
       {{"reflex.pairs=[[\"VAS\", \"BFS\"], [\"VAS\", \"TA\"]]"}, "reflex.pairs"}});
}

}  // namespace
}  // namespace pamsim
