// drop_mass_test.cc: the stretch reflex in the falling-mass experiment, end to end
// (scenarios/drop_mass.toml and drop_mass_fiber.toml against the passive baseline).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "base/units.h"
#include "pam_actuator/avbdl.h"
#include "sim/core/runner.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

std::string scenario_path(const char* name) {
  return std::string(PAMSIM_SOURCE_DIR) + "/scenarios/" + name;
}

TrialResult run(const char* name, const std::vector<std::string>& overrides = {},
                std::uint64_t seed = 1) {
  const Scenario sc = load_scenario(scenario_path(name), overrides);
  const TrialModel arm = load_trial_model(sc);
  return run_trial(arm, sc, seed);
}

TEST(DropMassTest, ModelReflexTriggersPromptlyWithoutMistripAndReducesTheDrop) {
  for (std::uint64_t seed : {1, 2, 3}) {
    const TrialResult reflex = run("drop_mass.toml", {}, seed);
    const TrialResult passive = run("drop_mass_passive.toml", {}, seed);
    const TrialSummary& s = reflex.summary;
    ASSERT_EQ(s.status, "ok") << s.message;
    ASSERT_TRUE(std::isfinite(s.metric("impact_time_s")));

    // no trigger in the quiet second before the impact; the agonist fires within 50 ms
    EXPECT_EQ(s.metric("mistrips"), 0) << "seed " << seed;
    EXPECT_GE(s.metric("reflex_triggers_ago"), 1);
    EXPECT_GE(s.metric("first_trigger_time_s"), s.metric("impact_time_s"));
    EXPECT_LE(s.metric("first_trigger_time_s") - s.metric("impact_time_s"), 0.050);

    // the arm drops less than without the reflex, with the same impact
    EXPECT_NEAR(passive.summary.metric("impact_time_s"), s.metric("impact_time_s"), 1e-9);
    EXPECT_GT(s.metric("min_angle_deg"), passive.summary.metric("min_angle_deg") + 0.5)
        << "seed " << seed;
  }
}

TEST(DropMassTest, AgonistCommandRisesDuringTheReflexWindow) {
  const TrialResult r = run("drop_mass.toml");
  const Trajectory& tr = r.trajectory;
  const std::size_t reflex = tr.column("reflex_ago"), cmd = tr.column("p_cmd_ago_MPa");
  const std::size_t cmd_anta = tr.column("p_cmd_anta_MPa");
  double peak = 0.0, trough_anta = 1.0;
  int window_rows = 0;
  for (std::size_t row = 0; row < tr.rows(); ++row) {
    if (tr.at(row, reflex) != 1.0) {
      EXPECT_NEAR(tr.at(row, cmd), 0.4, 1e-12) << "outside the window the goal holds";
      continue;
    }
    ++window_rows;
    peak = std::max(peak, tr.at(row, cmd));
    trough_anta = std::min(trough_anta, tr.at(row, cmd_anta));
  }
  EXPECT_EQ(window_rows, 20) << "one 200 ms window at 100 Hz";
  EXPECT_GT(peak, 0.45);         // excitation, Eq. (12)
  EXPECT_LT(trough_anta, 0.35);  // reciprocal inhibition, Eq. (13)
}

TEST(DropMassTest, FiberSensorReflexTriggersToo) {
  const TrialResult r = run("drop_mass_fiber.toml");
  EXPECT_EQ(r.summary.metric("mistrips"), 0);
  EXPECT_GE(r.summary.metric("reflex_triggers_ago"), 1);
  EXPECT_LE(r.summary.metric("first_trigger_time_s") - r.summary.metric("impact_time_s"), 0.050);
}

// The paper's Fig. 7: once the line is slack the gauge reads V_base and the estimated
// deformation is zero, so the length estimate is the natural length l_n(p) of the law the
// estimator inverts, Eq. (2). And the muscle itself rests at its free length: the plant's
// (the AVBDL law's zero-force length; with the ideal plant, l_n(p) again). The encoder, the
// fiber sensor and the error metrics see that, not the shorter distance the slack line
// leaves (which moves with the arm). Here the antagonist at 0.1 MPa is slack while the
// falling mass swings the arm, on the physical plant and on the ideal one.
TEST(DropMassTest, SlackLineLeavesTheMuscleAtItsFreeLength) {
  for (const char* name : {"drop_mass_passive.toml", "drop_mass_ideal.toml"}) {
    SCOPED_TRACE(name);
    const std::vector<std::string> quiet = {
        "reflex.enabled=false", "pressure.antagonist_MPa=0.1", "sim.duration_s=1.6",
        "sensors.gauge_noise_V=0.0", "sensors.gauge_adc_bits=0", "sensors.pressure_noise_MPa=0.0",
        "sensors.pressure_adc_bits=0", "sensors.fiber_noise_mm_s=0.0",
        // the instruments as exact (the shipped ones are hardware: the gauge's calibrated
        // V_base and the pressure sensor's offset are not the published constants)
        "sensors.pressure.model=\"ideal\"", "sensors.gauge.model=\"linear\"",
        "sensors.fiber.model=\"ideal\"", "sensors.encoder.model=\"ideal\""};
    const TrialResult r = run(name, quiet);
    ASSERT_EQ(r.summary.status, "ok") << r.summary.message;
    const Scenario sc = load_scenario(scenario_path(name), quiet);
    const MuscleSpec& anta = *sc.muscle("antagonist");
    const bool ideal = anta.plant_file.empty();
    const double v_base = anta.pam.strain_gauge->v_base_v;
    const SpringModel& spring = anta.pam.spring;
    const Trajectory& tr = r.trajectory;
    const std::size_t force = tr.column("force_anta_N"), gauge = tr.column("gauge_anta_V");
    const std::size_t est = tr.column("length_est_anta_mm"), p = tr.column("p_anta_MPa");
    const std::size_t length = tr.column("length_anta_mm");
    const std::size_t fiber = tr.column("fiber_rate_anta_mm_s");
    const std::size_t omega = tr.column("omega_deg_s");
    int slack_rows = 0, swinging_rows = 0;
    for (std::size_t row = 1; row < tr.rows(); ++row) {
      if (tr.at(row, force) > 0.0 || tr.at(row - 1, force) > 0.0) continue;
      ++slack_rows;
      const double p_pa = units::mpa_to_pa(tr.at(row, p));
      EXPECT_NEAR(tr.at(row, gauge), v_base, 1e-12) << "row " << row;
      // the muscle's length is where its own law stops pulling: the plant's static force
      // (Eq. 25) is zero there and positive a millimetre longer; the ideal plant's is l_n(p)
      const double length_m = units::mm_to_m(tr.at(row, length));
      const double l_n_mm = units::m_to_mm(spring.m_m_per_pa * p_pa + spring.h_m);  // Eq. (2)
      if (ideal) {
        EXPECT_NEAR(tr.at(row, length), l_n_mm, 1e-9) << "row " << row;
      } else {
        EXPECT_NEAR(avbdl_static_force(anta.plant, p_pa, length_m), 0.0, 1e-6) << "row " << row;
        EXPECT_GT(avbdl_static_force(anta.plant, p_pa, length_m + 0.001), 0.0) << "row " << row;
      }
      EXPECT_NEAR(tr.at(row, est), l_n_mm, 0.01) << "row " << row;
      // the free length moves only with the (regulated, near constant) pressure
      EXPECT_LT(std::fabs(tr.at(row, fiber)), 5.0) << "row " << row;
      if (std::fabs(tr.at(row, omega)) > 20.0) ++swinging_rows;
    }
    EXPECT_GT(slack_rows, 100) << "at 0.1 MPa the antagonist must be slack";
    EXPECT_GT(swinging_rows, 5) << "while the arm swings (a slack line's end moves with it)";
    // the ideal plant's estimate is exact; the fitted one is off by its l_n(p) misfit, which
    // below the tensile test's 0.2 MPa (an extrapolation) is centimetres, not millimetres
    if (ideal) {
      EXPECT_LT(r.summary.metric("length_est_max_error_mm"), 0.5);
    }
  }
}

// The shipped plant files edited by `edit`, written to the test's temp folder as
// <tag>_<muscle>.toml; the --set keys that use them.
std::vector<std::string> edited_plants(const std::string& tag,
                                       const std::function<void(std::string*)>& edit) {
  std::vector<std::string> sets;
  for (const std::string muscle : {"agonist", "antagonist"}) {
    std::ifstream in(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_" + muscle + ".toml");
    std::stringstream text;
    text << in.rdbuf();
    std::string plant = text.str();
    edit(&plant);
    const std::string path = ::testing::TempDir() + tag + "_" + muscle + ".toml";
    std::ofstream(path) << plant;
    sets.push_back("muscles." + muscle + ".plant=\"" + path + "\"");
  }
  return sets;
}

// After the drop the passive arm comes to rest. With the shipped tanh friction it creeps to
// the friction-free equilibrium (the plants without their [friction] tables); with
// Maxwell-slip braid friction (travels 0.1 and 0.5 mm) it stops within the friction band,
// 0.2 deg short of it. The drop itself, gross sliding over the same
// loop, hardly changes.
TEST(DropMassTest, MaxwellSlipFrictionStopsTheArmWhereTanhFrictionCreeps) {
  const std::vector<std::string> slip_plants = edited_plants("slip", [](std::string* plant) {
    const std::string smooth = "velocity_scale_mm_s = 1.0";
    plant->replace(plant->find(smooth), smooth.size(),
                   "model = \"maxwell_slip\"\nbreakaway_mm = [0.1, 0.5]\nweights = [0.5, 0.5]");
  });
  const auto strip_friction = [](std::string* plant) { plant->erase(plant->find("[friction]")); };
  const std::vector<std::string> no_friction = edited_plants("frictionless", strip_friction);
  const auto finish = [](std::vector<std::string> sets) {
    sets.push_back("sim.duration_s=5");
    const TrialResult r = run("drop_mass_passive.toml", sets);
    EXPECT_EQ(r.summary.status, "ok") << r.summary.message;
    return r.summary;
  };
  const TrialSummary smooth = finish({}), slip = finish(slip_plants);
  const double rest = finish(no_friction).metric("final_angle_deg");
  EXPECT_NEAR(smooth.metric("final_angle_deg"), rest, 0.01);
  EXPECT_GT(slip.metric("final_angle_deg") - rest, 0.1) << "held up by the stuck braid";
  EXPECT_NEAR(slip.metric("peak_drop_deg"), smooth.metric("peak_drop_deg"), 0.2);
}

// An extensible line (muscles.<m>.line_diameter_mm, line_modulus_MPa) keeps the calibrated
// start (its unstretched length is the calibrated one less the start tension's stretch),
// and, a soft spring in series with the muscle, lets the mass drop further; a creeping one
// too, and sags on after.
TEST(DropMassTest, ExtensibleLinesKeepTheStartAndSoftenTheArm) {
  const std::vector<std::string> nylon = {
      "muscles.agonist.line_diameter_mm=0.5", "muscles.agonist.line_modulus_MPa=2500",
      "muscles.antagonist.line_diameter_mm=0.5", "muscles.antagonist.line_modulus_MPa=2500"};
  const TrialResult rigid = run("drop_mass_passive.toml");
  const TrialResult soft = run("drop_mass_passive.toml", nylon);
  ASSERT_EQ(soft.summary.status, "ok") << soft.summary.message;
  const Trajectory& tr = soft.trajectory;
  const std::size_t t = tr.column("time_s"), angle = tr.column("angle_deg");
  for (std::size_t row = 0; row < tr.rows() && tr.at(row, t) < 0.99; ++row) {
    ASSERT_NEAR(tr.at(row, angle), -36.0, 1e-3) << "before the drop, t = " << tr.at(row, t);
  }
  EXPECT_GT(soft.summary.metric("peak_drop_deg"), rigid.summary.metric("peak_drop_deg") + 1.0);
  const Scenario a = load_scenario(scenario_path("drop_mass_passive.toml"), {});
  const Scenario b = load_scenario(scenario_path("drop_mass_passive.toml"), nylon);
  EXPECT_FALSE(same_trial_model(a, b));
  // a creeping line (line_creep 0.3 over 10 s) has crept under the start's tension before
  // the trial: the start still holds; under the mass it keeps stretching, so the arm ends lower
  std::vector<std::string> crept_lines = nylon;
  crept_lines.push_back("muscles.agonist.line_creep=0.3");
  crept_lines.push_back("muscles.antagonist.line_creep=0.3");
  const TrialResult crept = run("drop_mass_passive.toml", crept_lines);
  const Trajectory& ct = crept.trajectory;
  for (std::size_t row = 0; row < ct.rows() && ct.at(row, t) < 0.99; ++row) {
    ASSERT_NEAR(ct.at(row, angle), -36.0, 1e-3) << "crept, before the drop";
  }
  EXPECT_LT(crept.summary.metric("final_angle_deg"), soft.summary.metric("final_angle_deg") - 0.1);
  EXPECT_FALSE(
      same_trial_model(b, load_scenario(scenario_path("drop_mass_passive.toml"), crept_lines)));
}

// joints.<joint>.*: a bearing's damping and friction loss in place of the model's; more
// damping, less drop; a changed joint is a changed trial model (a sweep rebuilds it).
TEST(DropMassTest, JointKeysSetTheModelsDampingAndFrictionLoss) {
  const std::vector<std::string> damped = {"joints.shoulder.damping_N_m_s_per_rad=1.5",
                                           "joints.shoulder.frictionloss_N_m=0.02"};
  const Scenario base = load_scenario(scenario_path("drop_mass_passive.toml"), {});
  const Scenario sc = load_scenario(scenario_path("drop_mass_passive.toml"), damped);
  const TrialModel arm = load_trial_model(sc);
  const int dof = arm.model->jnt_dofadr[mj_name2id(arm.model.get(), mjOBJ_JOINT, "shoulder")];
  EXPECT_EQ(arm.model->dof_damping[dof], 1.5);
  EXPECT_EQ(arm.model->dof_frictionloss[dof], 0.02);
  const Scenario friction_only = load_scenario(scenario_path("drop_mass_passive.toml"),
                                               {"joints.shoulder.frictionloss_N_m=0.02"});
  EXPECT_EQ(load_trial_model(friction_only).model->dof_damping[dof], 0.1) << "the model's";
  EXPECT_FALSE(same_trial_model(base, sc));
  EXPECT_FALSE(same_trial_model(sc, friction_only));
  EXPECT_LT(run("drop_mass_passive.toml", damped).summary.metric("peak_drop_deg"),
            run("drop_mass_passive.toml").summary.metric("peak_drop_deg") - 0.5);
}

// The outcome metrics agree with the trajectory they summarise, recomputed here from the log
// by other means than the metrics use (they read contacts and the controller's trigger
// times): mass_retained with where the ball ends, mistrips and retriggers with the reflex
// windows the log shows, the length errors in % with the logged lengths.
TEST(DropMassTest, OutcomeMetricsAgreeWithTheTrajectory) {
  // the shipped scenarios keep the mass without retriggers; the fiber reflex on the ideal
  // plant loses it and retriggers (docs/findings.md), so both branches are checked
  const std::vector<std::string> ideal_fiber = {"reflex.sensor=\"fiber\"", "reflex.v_thr_mm_s=25",
                                                "reflex.k_MPa_s_per_mm=0.0033333333333333335"};
  const std::vector<std::pair<const char*, std::vector<std::string>>> cases = {
      {"drop_mass.toml", {}},
      {"drop_mass_fiber.toml", {}},
      {"drop_mass_passive.toml", {}},
      {"drop_mass_ideal.toml", ideal_fiber}};
  for (const auto& [name, overrides] : cases) {
    SCOPED_TRACE(name);
    const TrialResult r = run(name, overrides);
    ASSERT_EQ(r.summary.status, "ok") << r.summary.message;
    const TrialSummary& s = r.summary;
    const Trajectory& tr = r.trajectory;

    // the ball in the basket (~0.8 m up) or on the floor (its radius, 18 mm)
    const double ball_z = tr.at(tr.rows() - 1, tr.column("ball_z_m"));
    ASSERT_TRUE(ball_z > 0.5 || ball_z < 0.05) << ball_z;
    EXPECT_EQ(s.metric("mass_retained"), ball_z > 0.5 ? 1.0 : 0.0);

    // counted again from the log: a trigger opens a reflex window (reflex_<m> rises from 0
    // to 1); one before the impact is a mistrip, the first after it the response, the rest
    // retriggers
    const double impact = s.metric("impact_time_s");
    int before = 0, after = 0;
    for (const char* m : {"ago", "anta"}) {
      const std::size_t window = tr.column(std::string("reflex_") + m);
      for (std::size_t row = 0; row < tr.rows(); ++row) {
        const bool opens = tr.at(row, window) == 1.0 && (row == 0 || tr.at(row - 1, window) == 0.0);
        if (opens) ++(tr.at(row, tr.column("time_s")) < impact ? before : after);
      }
    }
    EXPECT_EQ(s.metric("mistrips"), before);
    EXPECT_EQ(s.metric("retriggers_after_impact"), std::max(after - 1, 0));

    // the pooled length error in % of the true length
    double sum_sq = 0.0, max_abs = 0.0;
    for (std::size_t row = 0; row < tr.rows(); ++row) {
      for (const char* m : {"ago", "anta"}) {
        const double truth = tr.at(row, tr.column(std::string("length_") + m + "_mm"));
        const double est = tr.at(row, tr.column(std::string("length_est_") + m + "_mm"));
        const double e = 100.0 * (est - truth) / truth;
        sum_sq += e * e;
        max_abs = std::max(max_abs, std::fabs(e));
      }
    }
    EXPECT_NEAR(s.metric("length_est_rmse_pct"), std::sqrt(sum_sq / (2.0 * tr.rows())), 1e-12);
    EXPECT_EQ(s.metric("length_est_max_error_pct"), max_abs);
  }
  // the model-based reflex keeps the mass (the passive arm does too); the ideal fiber case
  // exercises the other branches
  EXPECT_EQ(run("drop_mass.toml").summary.metric("mass_retained"), 1.0);
  const TrialSummary lost = run("drop_mass_ideal.toml", ideal_fiber).summary;
  EXPECT_EQ(lost.metric("mass_retained"), 0.0);
  EXPECT_GE(lost.metric("retriggers_after_impact"), 1.0);
}

}  // namespace
}  // namespace pamsim
