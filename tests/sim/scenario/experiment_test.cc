// experiment_test.cc: the papers' other experiments and new casts run on the same core, from
// scenario data alone: the pulley's hanging weight follows its PAM, the reaching arm rises
// monotonically while the ramps run, a model with a third PAM runs with no code for it, the
// events (add a mass, end on a time, a joint or a body height, switch the controller) do what
// they say, and the drop written in the long form is the shorthand's trial bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/three_pam_model.h"
#include "sim/core/runner.h"
#include "sim/core/trial.h"
#include "sim/scenario/scenario_file.h"
#include "sim/test_paths.h"

namespace pamsim {
namespace {

using pamsim_test::kScenarios;
using pamsim_test::kSource;

TrialResult run_file(const std::string& name, const std::vector<std::string>& overrides = {}) {
  const Scenario sc = load_scenario(kScenarios + name, overrides);
  return run_trial(load_trial_model(sc), sc, sc.seed);
}

// A scenario written as text, read as if it lay in scenarios/ (so ../models/... resolves).
TrialResult run_text(const std::string& text) {
  const Scenario sc = load_scenario_text(text, kScenarios + "inline.toml");
  return run_trial(load_trial_model(sc), sc, sc.seed);
}

std::vector<double> column(const Trajectory& tr, const std::string& name) {
  const std::size_t c = tr.column(name);
  std::vector<double> v(tr.rows());
  for (std::size_t r = 0; r < tr.rows(); ++r) v[r] = tr.at(r, c);
  return v;
}

bool bit_identical(const Trajectory& a, const Trajectory& b) {
  return a.columns == b.columns && a.values.size() == b.values.size() &&
         std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(double)) == 0;
}

// The passive drop without its ball, the arm at rest at -36 deg: a base for event tests.
const char* kQuietArm = R"(
seed = 1
metrics = ["tracking"]
[model]
file = "../models/arm_2pam.xml"
joint = "shoulder"
calibration = "../models/arm_2pam_calibration.toml"
pneumatics = "../models/pams/pneumatics.toml"
[sim]
duration_s = 3.0
[muscles.agonist]
params = "../models/pams/table4_agonist.toml"
command = { kind = "constant", MPa = 0.4 }
[muscles.antagonist]
params = "../models/pams/table4_antagonist.toml"
command = { kind = "constant", MPa = 0.4 }
[controller]
kind = "none"
)";

// --- the pulley ------------------------------------------------------------------------

// The weight hangs from the PAM's line over the pulley: it rises exactly as much as the
// PAM shortens (an inextensible line in MuJoCo's tendon), while the sine swings the PAM by
// millimetres.
TEST(ExperimentTest, PulleyWeightFollowsThePam) {
  const TrialResult r = run_file("pulley_sine_5kg.toml", {"sim.duration_s=10"});
  ASSERT_EQ(r.summary.status, "ok") << r.summary.message;
  const std::vector<double> x = column(r.trajectory, "position_mm");
  const std::vector<double> len = column(r.trajectory, "length_pam_mm");
  const std::vector<double> cmd = column(r.trajectory, "p_cmd_pam_MPa");
  double swing_min = 1e9, swing_max = -1e9;
  for (std::size_t k = 0; k < x.size(); ++k) {
    EXPECT_NEAR(x[k] - x[0], -(len[k] - len[0]), 0.5) << "row " << k;
    swing_min = std::min(swing_min, x[k]);
    swing_max = std::max(swing_max, x[k]);
  }
  EXPECT_GT(swing_max - swing_min, 10.0) << "the sine moves the weight by more than 10 mm";

  // it starts at rest at the slide's zero (the equilibrium line), and the command is the
  // papers' p = 0.2 sin(2 pi t / 5) + 0.6 MPa
  EXPECT_NEAR(x[0], 0.0, 0.01);
  const std::vector<double> t = column(r.trajectory, "time_s");
  for (std::size_t k = 0; k < t.size(); k += 37) {
    EXPECT_NEAR(cmd[k], 0.2 * std::sin(2 * M_PI * t[k] / 5) + 0.6, 1e-9) << t[k];
  }
  // high pressure shortens the PAM: the weight is highest near the sine's top (t = 1.25 s,
  // 6.25 s), lowest near its bottom, a little later (the valve and chamber lag)
  const auto at = [&](double time) { return x[static_cast<std::size_t>(std::lround(time * 100))]; };
  EXPECT_GT(at(6.5), at(4.0) + 10.0);
  EXPECT_GT(at(6.5), x[0]);
  EXPECT_LT(at(9.0), x[0]);
  EXPECT_LT(r.summary.metric("pressure_rmse_pam_MPa"), 0.02);
}

TEST(ExperimentTest, HeavierWeightHangsLowerAtTheSamePressure) {
  // same line (solved for 5 kg at 0.6 MPa), twice the weight: the PAM stretches further
  const TrialResult five = run_file("pulley_sine_5kg.toml", {"sim.duration_s=3"});
  const TrialResult ten = run_file("pulley_sine_10kg.toml", {"sim.duration_s=3"});
  ASSERT_EQ(ten.summary.status, "ok") << ten.summary.message;
  // each solves its own line, so both start at rest at zero; the heavier one's PAM is longer
  const std::vector<double> len5 = column(five.trajectory, "length_pam_mm");
  const std::vector<double> len10 = column(ten.trajectory, "length_pam_mm");
  EXPECT_GT(len10[0], len5[0] + 1.0);
  EXPECT_NEAR(column(ten.trajectory, "position_mm")[0], 0.0, 0.01);
}

TEST(ExperimentTest, PulleyTrialsAreTheSameOnOneAndTwoThreads) {
  const Scenario sc = load_scenario(kScenarios + "pulley_sine_5kg.toml", {"sim.duration_s=2"});
  const TrialModel rig = load_trial_model(sc);
  const auto one = run_trials(rig, sc, 4, 1);
  const auto two = run_trials(rig, sc, 4, 2);
  ASSERT_EQ(one.size(), 4u);
  ASSERT_EQ(two.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_TRUE(bit_identical(one[k].trajectory, two[k].trajectory)) << "trial " << k;
  }
}

// --- a physical plant ------------------------------------------------------------------

// The pulley's PAM as the AVBDL law of Pipan et al. (models/pams/plant_agonist.toml) while the
// estimator still inverts Table IV's spring law: the line solved for the plant holds the
// weight at rest, and the estimator is now wrong by what separates the two laws.
TEST(ExperimentTest, PulleyWithAPhysicalPlantHoldsItsWeightAndShowsTheEstimatorsError) {
  const std::string plant = "muscles.pam.plant=\"../models/pams/plant_agonist.toml\"";
  const TrialResult still = run_file(
      "pulley_sine_5kg.toml",
      {plant, "sim.duration_s=2", "muscles.pam.command={ kind = \"constant\", MPa = 0.6 }"});
  ASSERT_EQ(still.summary.status, "ok") << still.summary.message;
  for (double x : column(still.trajectory, "position_mm")) EXPECT_NEAR(x, 0.0, 0.05);
  const std::vector<double> force = column(still.trajectory, "force_pam_N");
  EXPECT_NEAR(force.back(), 5.0 * 9.81, 0.05);

  const TrialResult ideal = run_file("pulley_sine_5kg.toml", {"sim.duration_s=10"});
  const TrialResult physical = run_file("pulley_sine_5kg.toml", {plant, "sim.duration_s=10"});
  ASSERT_EQ(physical.summary.status, "ok") << physical.summary.message;
  EXPECT_LT(ideal.summary.metric("length_est_rmse_pam_pct"), 0.2);
  EXPECT_GT(physical.summary.metric("length_est_rmse_pam_pct"), 1.0);
  // the weight still follows the sine, by the plant's own stiffness
  EXPECT_GT(physical.summary.metric("position_max_mm") - physical.summary.metric("position_min_mm"),
            5.0);
}

// --- reaching --------------------------------------------------------------------------

TEST(ExperimentTest, ReachingArmRisesMonotonicallyWhileTheRampsRun) {
  const TrialResult r = run_file("reaching.toml");
  ASSERT_EQ(r.summary.status, "ok") << r.summary.message;
  const std::vector<double> t = column(r.trajectory, "time_s");
  const std::vector<double> angle = column(r.trajectory, "angle_deg");
  const std::vector<double> ago = column(r.trajectory, "p_cmd_ago_MPa");
  const std::vector<double> anta = column(r.trajectory, "p_cmd_anta_MPa");
  const std::vector<double> len_anta = column(r.trajectory, "length_anta_mm");
  const std::vector<double> est_anta = column(r.trajectory, "length_est_anta_mm");
  double start = NAN, end = NAN;
  for (std::size_t k = 1; k < t.size(); ++k) {
    if (t[k] <= 2.0 || t[k] > 14.0) continue;  // while the ramps run
    // never back down (by more than the braid friction's creep before it breaks away)
    EXPECT_GT(angle[k], angle[k - 1] - 0.01) << "t = " << t[k];
    if (std::isnan(start)) start = angle[k - 1];
    end = angle[k];
    // the fitted estimator is off by Table V's order on the physical plant, not more
    EXPECT_LT(std::fabs(est_anta[k] - len_anta[k]), 0.03 * len_anta[k]) << "t = " << t[k];
  }
  EXPECT_GT(end - start, 40.0) << "from " << start << " to " << end << " deg";
  // the commands are the ramps: 0.2 -> 0.6 and 0.6 -> 0.2 MPa over 2..14 s
  const std::size_t mid = 800;  // t = 8 s
  ASSERT_NEAR(t[mid], 8.0, 1e-9);
  EXPECT_NEAR(ago[mid], 0.4, 1e-9);
  EXPECT_NEAR(anta[mid], 0.4, 1e-9);
  EXPECT_NEAR(ago.back(), 0.6, 1e-9);
  EXPECT_NEAR(anta.back(), 0.2, 1e-9);
  // the agonist's line stays taut; the antagonist's is slack in the first swing from the
  // calibrated -36 deg to the ramps' starting pressures, taut mid-ramp, and slack again at
  // the top, where its pressure has fallen to 0.2 MPa (the slack episode that
  // `pamsim validate reaching` finds)
  const std::vector<double> force_anta = column(r.trajectory, "force_anta_N");
  EXPECT_GT(force_anta[mid], 5.0);
  EXPECT_EQ(force_anta.back(), 0.0);
  EXPECT_GT(column(r.trajectory, "force_ago_N").back(), 10.0);
  EXPECT_EQ(*std::min_element(force_anta.begin() + 1, force_anta.begin() + 30), 0.0);
}

// --- a third PAM -----------------------------------------------------------------------

// clang-format off
TEST(ExperimentTest, AThirdPamRunsWithNoChangeToTheCode) {
  const auto dir = pamsim_test::fresh_dir("three_pam");
  pamsim_test::write_text(dir / "arm_3pam.xml", pamsim_test::three_pam_model());
  const std::string models = kSource + "/models/";
  // the reflex pairs the first two; the second agonist, unpaired, follows its schedule:
  // relaxed (slack) until 1.5 s, then 0.6 MPa, which pulls the arm up
  const std::string text = "seed = 1\n"
                           "[model]\n"
                           "file = \"arm_3pam.xml\"\n"
                           "calibration = \"" + models + "arm_2pam_calibration.toml\"\n"
                           "pneumatics = \"" + models + "pams/pneumatics.toml\"\n"
                           "[sim]\nduration_s = 3.0\n"
                           "[muscles.agonist]\n"
                           "params = \"" + models + "pams/table4_agonist.toml\"\n"
                           "command = { kind = \"constant\", MPa = 0.4 }\n"
                           "[muscles.antagonist]\n"
                           "params = \"" + models + "pams/table4_antagonist.toml\"\n"
                           "command = { kind = \"constant\", MPa = 0.4 }\n"
                           "[muscles.agonist2]\n"
                           "label = \"ago2\"\n"
                           "params = \"" + models + "pams/table4_agonist.toml\"\n"
                           "line_mm = 302.44573247\n"
                           "command = { kind = \"steps\", times_s = [0.0, 1.5], MPa = [0.0, 0.6] }\n"
                           "[holds.ball]\nposition_m = [0.5, 0.5, 0.5]\n"
                           "[controller]\nkind = \"stretch_reflex\"\n"
                           "[reflex]\npairs = [[\"agonist\", \"antagonist\"]]\n";
  pamsim_test::write_text(dir / "three.toml", text);
  const Scenario sc = load_scenario((dir / "three.toml").string());
  ASSERT_EQ(sc.muscles.size(), 3u);
  const TrialResult r = run_trial(load_trial_model(sc), sc, sc.seed);
  ASSERT_EQ(r.summary.status, "ok") << r.summary.message;

  const Trajectory& tr = r.trajectory;
  for (const char* name : {"p_cmd_ago2_MPa", "p_ago2_MPa", "force_ago2_N", "length_ago2_mm",
                           "length_est_ago2_mm", "reflex_ago2", "gauge_ago2_V"}) {
    EXPECT_TRUE(tr.has_column(name)) << name;
  }
  const std::vector<double> t = column(tr, "time_s");
  const std::vector<double> cmd2 = column(tr, "p_cmd_ago2_MPa");
  const std::vector<double> angle = column(tr, "angle_deg");
  const std::vector<double> force2 = column(tr, "force_ago2_N");
  for (std::size_t k = 0; k < t.size(); ++k) {
    EXPECT_EQ(cmd2[k], t[k] < 1.5 ? 0.0 : 0.6) << "t = " << t[k];   // passed through
    if (t[k] < 1.5) {
      EXPECT_NEAR(angle[k], -36.0, 0.5) << "t = " << t[k];   // the pair holds the arm
      EXPECT_EQ(force2[k], 0.0) << "slack at 0 MPa, t = " << t[k];
    }
  }
  EXPECT_GT(angle.back(), -36.0 + 5.0) << "the second agonist lifts the arm";
  EXPECT_GT(force2.back(), 10.0);
  EXPECT_FALSE(std::isnan(r.summary.metric("reflex_triggers_ago2")));
}
// clang-format on

// --- events ----------------------------------------------------------------------------

TEST(ExperimentTest, EndEventsStopTheTrialOnATimeAJointOrABodyHeight) {
  // at a time
  const TrialResult timed =
      run_text(std::string(kQuietArm) + "[events.stop]\naction = \"end\"\nwhen.at_s = 1.25\n");
  ASSERT_EQ(timed.summary.status, "ok") << timed.summary.message;
  EXPECT_NEAR(timed.summary.metric("sim_time_s"), 1.25, 1e-6);
  EXPECT_NE(timed.summary.message.find("stop"), std::string::npos) << timed.summary.message;
  EXPECT_NEAR(column(timed.trajectory, "time_s").back(), 1.25, 0.011);

  // on the joint: a 1 kg payload added to the basket at 1 s drops the arm; the trial ends
  // on the first step the angle is below -40 deg
  const std::string payload = std::string(kQuietArm) +
                              "[events.load]\naction = \"add_mass\"\nbody = \"basket\"\n"
                              "mass_kg = 1.0\nwhen.at_s = 1.0\n";
  const TrialResult loaded = run_text(payload);
  ASSERT_EQ(loaded.summary.status, "ok");
  EXPECT_NEAR(loaded.summary.metric("angle_start_deg"), -36.0, 0.5);
  EXPECT_LT(loaded.summary.metric("angle_min_deg"), -45.0) << "the payload pulls the arm down";
  const TrialResult ended = run_text(payload +
                                     "[events.low]\naction = \"end\"\nafter = \"load\"\n"
                                     "when = { joint = \"shoulder\", below_deg = -40 }\n");
  ASSERT_EQ(ended.summary.status, "ok");
  const double t_low = ended.summary.metric("sim_time_s");
  EXPECT_GT(t_low, 1.0);
  EXPECT_LT(t_low, 1.5);
  EXPECT_LE(ended.summary.metric("angle_final_deg"), -40.0 + 0.5);
  EXPECT_GT(ended.summary.metric("angle_final_deg"), -41.0);

  // on a body's height: the ball released from 1.5 m ends the trial as it passes 1.0 m,
  // sqrt(2 * 0.5 / g) = 0.319 s later
  const TrialResult fell = run_text(std::string(kQuietArm) +
                                    "[holds.ball]\nposition_m = [0.5, 0.5, 1.5]\n"
                                    "[events.drop]\naction = \"release\"\nbody = \"ball\"\n"
                                    "when.at_s = 0.5\n"
                                    "[events.passed]\naction = \"end\"\n"
                                    "when = { body = \"ball\", below_z_m = 1.0 }\n");
  ASSERT_EQ(fell.summary.status, "ok");
  EXPECT_NEAR(fell.summary.metric("sim_time_s"), 0.5 + std::sqrt(2 * 0.5 / 9.81), 0.003);
}

TEST(ExperimentTest, ControllerOffBeforeTheImpactKeepsTheReflexSilent) {
  const TrialResult reflex = run_file("drop_mass.toml", {"sim.duration_s=2"});
  ASSERT_GE(reflex.summary.metric("reflex_triggers_ago"), 1.0);
  const std::string text = pamsim_test::read_file(kScenarios + "drop_mass.toml");
  const std::string off_then_on =
      "[events.off]\naction = \"controller_off\"\nwhen.at_s = 1.1\n"
      "[events.on]\naction = \"controller_on\"\nwhen.at_s = 1.9\n";
  const Scenario sc =
      load_scenario_text(text + off_then_on, kScenarios + "inline.toml", {"sim.duration_s=2"});
  const TrialResult off = run_trial(load_trial_model(sc), sc, sc.seed);
  ASSERT_EQ(off.summary.status, "ok");
  EXPECT_EQ(off.summary.metric("reflex_triggers_ago"), 0.0);
  EXPECT_TRUE(std::isnan(off.summary.metric("first_trigger_time_s")));
  EXPECT_LT(off.summary.metric("min_angle_deg"), reflex.summary.metric("min_angle_deg") - 1.0)
      << "without the reflex the arm drops further";
  // the commands are the schedules' while it is off
  const std::vector<double> t = column(off.trajectory, "time_s");
  const std::vector<double> ago = column(off.trajectory, "p_cmd_ago_MPa");
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] > 1.1 && t[k] < 1.9) {
      EXPECT_EQ(ago[k], 0.4) << t[k];
    }
  }
}

// --- the drop, long form and shorthand --------------------------------------------------

// pamsim 0.1 always had the drop, with its defaults (0.2 kg, 14 cm, at 1 s) when a file gave
// no [drop] table: such a file still runs the same trial.
TEST(ExperimentTest, APamsim01FileWithoutADropTableStillDrops) {
  std::string text = pamsim_test::read_file(kScenarios + "drop_mass.toml");
  const std::string table = "[drop]\nmass_kg = 0.2\nheight_m = 0.14\ntime_s = 1.0\n";
  const auto at = text.find(table);
  ASSERT_NE(at, std::string::npos) << "drop_mass.toml's [drop] table changed";
  text.erase(at, table.size());
  const TrialResult without = run_text(text);
  const TrialResult with = run_file("drop_mass.toml");
  ASSERT_EQ(without.summary.status, "ok") << without.summary.message;
  EXPECT_TRUE(bit_identical(without.trajectory, with.trajectory));
  EXPECT_EQ(without.summary.metric("impact_time_s"), with.summary.metric("impact_time_s"));
}

TEST(ExperimentTest, DropInTheLongFormIsTheShorthandsTrialBitForBit) {
  // drop_mass.toml written out without the shorthands (as if it lay in scenarios/)
  const std::string long_form =
      pamsim_test::read_file(kSource + "/tests/sim/data/drop_mass_long_form.toml");
  const TrialResult shorthand = run_file("drop_mass.toml", {"sim.duration_s=2"});
  const TrialResult longhand = run_text(long_form);
  ASSERT_EQ(longhand.summary.status, "ok") << longhand.summary.message;
  EXPECT_TRUE(bit_identical(shorthand.trajectory, longhand.trajectory));
  ASSERT_EQ(shorthand.summary.metrics.size(), longhand.summary.metrics.size());
  for (std::size_t k = 0; k < shorthand.summary.metrics.size(); ++k) {
    const Metric& a = shorthand.summary.metrics[k];
    const Metric& b = longhand.summary.metrics[k];
    EXPECT_EQ(a.name, b.name);
    if (is_timing_metric(a.name)) continue;
    EXPECT_TRUE(a.value == b.value || (std::isnan(a.value) && std::isnan(b.value))) << a.name;
  }
}

}  // namespace
}  // namespace pamsim
