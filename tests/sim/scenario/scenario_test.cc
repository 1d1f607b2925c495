// scenario_test.cc: every scenario key is validated with one clear message naming the file
// and the key; unknown keys, broken files and broken models are refused.
#include "sim/scenario/scenario_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "reflex/stretch_reflex_controller.h"
#include "sim/core/runner.h"
#include "sim/scenario_errors.h"

namespace pamsim {
namespace {

const std::string kScenario = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml";

// The message of loading and binding with `overrides`, or "" if none.
std::string error_of(const std::vector<std::string>& overrides,
                     const std::string& path = kScenario) {
  return pamsim_test::error_of(path, overrides);
}

std::string pamsim_test_read(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string write_temp(const std::string& name, const std::string& text) {
  // ctest runs each test in its own process, in parallel: keep their files apart
  const std::string path = ::testing::TempDir() + std::to_string(::getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(ScenarioTest, ShippedScenariosLoad) {
  for (const char* name : {"drop_mass.toml", "drop_mass_passive.toml", "drop_mass_fiber.toml",
                           "drop_mass_ideal.toml"}) {
    EXPECT_EQ(error_of({}, std::string(PAMSIM_SOURCE_DIR) + "/scenarios/" + name), "") << name;
  }
  const Scenario sc = load_scenario(kScenario);
  const StretchReflexScenarioConfig* reflex = sc.controller_config<StretchReflexScenarioConfig>();
  ASSERT_NE(reflex, nullptr);
  EXPECT_DOUBLE_EQ(reflex->reflex.v_thr_m_s, 70.0e-3);                // 70 mm/s
  EXPECT_DOUBLE_EQ(reflex->reflex.k_pa_s_per_m, 1e6 / 800.0 / 1e-3);  // 1/800 MPa s/mm
  EXPECT_DOUBLE_EQ(sc.muscle("agonist")->command.at(0.0), 0.4e6);
}

TEST(ScenarioTest, OverridesTakeEffect) {
  const Scenario sc =
      load_scenario(kScenario, {"reflex.v_thr_mm_s=55", "seed=9", "valve.model=first_order"});
  EXPECT_DOUBLE_EQ(sc.controller_config<StretchReflexScenarioConfig>()->reflex.v_thr_m_s, 55.0e-3);
  EXPECT_EQ(sc.seed, 9u);
  EXPECT_EQ(sc.valve_model, ValveModel::kFirstOrder);
}

// A plant must be the muscle its estimator file describes: its length and braid angle are
// the ones of that file's [geometry] (the diameter may differ, as plant_agonist.toml's does).
TEST(ScenarioTest, PlantMustBeTheMuscleItsEstimatorDescribes) {
  std::string text =
      pamsim_test_read(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_agonist.toml");
  const std::string angle = "braid_angle_deg = 25";
  ASSERT_NE(text.find(angle), std::string::npos);
  text.replace(text.find(angle), angle.size(), "braid_angle_deg = 30");
  const std::string plant = write_temp("plant_30deg.toml", text);
  EXPECT_NE(error_of({"muscles.agonist.plant=\"" + plant + "\""})
                .find("muscles.agonist.plant has a braid angle of 30 deg, but its estimator's"),
            std::string::npos);
  EXPECT_EQ(error_of({"muscles.agonist.plant=\"../models/pams/plant_agonist.toml\""}), "");
}

// valve.dead_time_ms, valve.valve_time_constant_ms and valve.proportional_band_kPa replace
// the pneumatics file's [regulator] values, scaled as the file's keys are; absent, the
// file's values stand.
TEST(ScenarioTest, RegulatorKeysOverrideThePneumaticsFile) {
  const Scenario base = load_scenario(kScenario);
  // the shipped ITV1000-class loop (models/pams/pneumatics.toml [regulator])
  EXPECT_EQ(base.pneumatics.regulator_dead_time_s, 10.0 * 1e-3);
  EXPECT_EQ(base.pneumatics.regulator_valve_time_constant_s, 20.0 * 1e-3);
  EXPECT_EQ(base.pneumatics.regulator_proportional_band_pa, 380.0 * 1e3);
  const Scenario sc = load_scenario(
      kScenario,
      {"valve.dead_time_ms=2", "valve.valve_time_constant_ms=5", "valve.proportional_band_kPa=50"});
  EXPECT_EQ(sc.pneumatics.regulator_dead_time_s, 2.0 * 1e-3);
  EXPECT_EQ(sc.pneumatics.regulator_valve_time_constant_s, 5.0 * 1e-3);
  EXPECT_EQ(sc.pneumatics.regulator_proportional_band_pa, 50.0 * 1e3);
  // another valve model would ignore them: refused, by key
  const std::string ideal = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass_ideal.toml";
  EXPECT_NE(error_of({"valve.dead_time_ms=5"}, ideal).find("valve.dead_time_ms is used only by"),
            std::string::npos);
  EXPECT_EQ(error_of({"valve.dead_time_ms=5", "valve.model=\"regulator\""}, ideal), "");
}

// The loop's feedback path and restrictions as scenario keys: a point of
// the bracket over the pneumatics file's [regulator]; absent, the file's model stands.
TEST(ScenarioTest, RegulatorLoopKeysOverrideThePneumaticsFile) {
  const Scenario base = load_scenario(kScenario);
  // the shipped loop: delayed, on the outlet, the ITV1000's conductance
  EXPECT_EQ(base.pneumatics.regulator_feedback, RegulatorFeedback::kDelayed);
  EXPECT_EQ(base.pneumatics.regulator_sense, RegulatorSense::kOutlet);
  EXPECT_NEAR(*base.pneumatics.regulator_supply_conductance_m3_per_s_pa, 0.35e-8, 1e-22);
  const Scenario sc = load_scenario(
      kScenario,
      {"valve.feedback=\"instant\"", "valve.sense=\"chamber\"", "valve.sample_period_ms=0.5",
       "valve.supply_sonic_conductance_dm3_per_s_bar=0.5",
       "valve.supply_critical_pressure_ratio=0.25",
       "valve.exhaust_sonic_conductance_dm3_per_s_bar=0.2",
       "valve.exhaust_critical_pressure_ratio=0.35", "valve.outlet_volume_cm3=3",
       "valve.tube_sonic_conductance_dm3_per_s_bar=2", "valve.tube_critical_pressure_ratio=0.45"});
  const PneumaticParams& p = sc.pneumatics;
  EXPECT_EQ(p.regulator_feedback, RegulatorFeedback::kInstant);
  EXPECT_EQ(p.regulator_sense, RegulatorSense::kChamber);
  EXPECT_EQ(p.regulator_sample_period_s, 0.5 * 1e-3);
  EXPECT_NEAR(*p.regulator_supply_conductance_m3_per_s_pa, 0.5e-8, 1e-22);
  EXPECT_EQ(*p.regulator_supply_critical_ratio, 0.25);
  EXPECT_NEAR(*p.regulator_exhaust_conductance_m3_per_s_pa, 0.2e-8, 1e-22);
  EXPECT_EQ(*p.regulator_exhaust_critical_ratio, 0.35);
  EXPECT_NEAR(p.regulator_outlet_volume_m3, 3e-6, 1e-18);
  EXPECT_NEAR(p.tube_conductance_m3_per_s_pa, 2e-8, 1e-22);
  EXPECT_EQ(p.tube_critical_ratio, 0.45);
  const std::string ideal = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass_ideal.toml";
  EXPECT_NE(error_of({"valve.feedback=\"delayed\""}, ideal).find("valve.feedback is used only by"),
            std::string::npos);
}

// An instrument's hardware keys with its ideal model would be ignored: refused, by key, as
// the valve's regulator keys are with another valve.
TEST(ScenarioTest, HardwareKeysOfAnIdealInstrumentAreRefused) {
  struct Case {
    std::vector<std::string> set;
    std::string says;
  };
  for (const Case& c : std::vector<Case>{
           {{"sensors.gauge.model=\"linear\"", "sensors.gauge.contact.misalignment_mm=300"},
            "sensors.gauge.contact.misalignment_mm is used only by sensors.gauge.model = "
            "\"bridge\", not \"linear\""},
           {{"sensors.pressure.model=\"ideal\"", "sensors.pressure.response_time_ms=5"},
            "sensors.pressure.response_time_ms is used only by sensors.pressure.model = "
            "\"pse540\""},
           {{"sensors.fiber.model=\"ideal\"", "sensors.fiber.span_mm=30"},
            "sensors.fiber.span_mm is used only by sensors.fiber.model = \"fabric\""},
           {{"sensors.encoder.model=\"ideal\"", "sensors.encoder.resolution_mm=0.1"},
            "sensors.encoder.resolution_mm is used only by sensors.encoder.model = \"counts\""}}) {
    EXPECT_NE(error_of(c.set).find(c.says), std::string::npos) << c.says << ": " << error_of(c.set);
  }
  // the model alone, either way, is fine
  EXPECT_EQ(error_of({"sensors.gauge.model=\"linear\""}), "");
}

// The gauge's creep is two lists: a bad weight is named with its index.
TEST(ScenarioTest, ABadGaugeCreepTermIsNamedWithItsIndex) {
  const std::string message = error_of({"sensors.gauge.board.creep_weights=[0.02, -0.1]",
                                        "sensors.gauge.board.creep_times_s=[1, 60]"});
  EXPECT_NE(message.find("sensors.gauge.board.creep_weights[1] must be in [0, inf)"),
            std::string::npos)
      << message;
}

// The gauge as hardware reaches the trial: its calibrated Eq. (8) reads the force back, and
// the same instrument seed builds the same gauges whatever the trial's seed.
TEST(ScenarioTest, TheGaugeAsHardwareIsCalibratedAndReadsTheForce) {
  // the board held still (its ringing at the impact: the test after this one)
  const std::vector<std::string> bridge = {"sensors.gauge.model=\"bridge\"",
                                           "sensors.gauge.board.vibration=false",
                                           "sensors.gauge_noise_V=0", "sim.duration_s=1.5"};
  const Scenario sc = load_scenario(kScenario, bridge);
  EXPECT_TRUE(sc.sensing.sensors.gauge_hardware.enabled);
  const TrialModel arm = load_trial_model(sc);
  const TrialResult a = run_trial(arm, sc, 1);
  ASSERT_EQ(a.summary.status, "ok") << a.summary.message;
  const Trajectory& tr = a.trajectory;
  const std::size_t force = tr.column("force_ago_N"), meas = tr.column("force_meas_ago_N");
  double worst = 0.0;
  for (std::size_t row = 0; row < tr.rows(); ++row) {
    worst = std::max(worst, std::fabs(tr.at(row, meas) - tr.at(row, force)));
  }
  // the ADC (16 bit over 10 V: 0.07 N) and the bridge's bend beyond the calibrated line
  EXPECT_LT(worst, 1.0);
  // deterministic, and another trial seed builds the same gauges: the first tick's reading
  // (no gauge noise; the force is the calibrated start's) is the same
  const TrialResult again = run_trial(arm, sc, 1);
  EXPECT_EQ(again.trajectory.at(tr.rows() - 1, meas), tr.at(tr.rows() - 1, meas));
  const TrialResult other = run_trial(arm, sc, 2);
  EXPECT_EQ(other.trajectory.at(0, meas), tr.at(0, meas));
}

// The gauge board's ringing reaches the trial: at rest it reads as the still board does,
// at the impact (1.17 s) it reads the bend of the moment, not the pull.
TEST(ScenarioTest, TheRingingBoardReadsAsTheStillOneButAtTheImpact) {
  const std::vector<std::string> base = {"sensors.gauge_noise_V=0", "sim.duration_s=1.3"};
  std::vector<std::string> still = base;
  still.push_back("sensors.gauge.board.vibration=false");
  const Scenario a = load_scenario(kScenario, base), b = load_scenario(kScenario, still);
  const TrialResult ringing = run_trial(load_trial_model(a), a, 1);
  const TrialResult held = run_trial(load_trial_model(b), b, 1);
  const Trajectory& tr = ringing.trajectory;
  ASSERT_EQ(tr.rows(), held.trajectory.rows());
  const std::size_t meas = tr.column("force_meas_ago_N"), time = tr.column("time_s");
  double before = 0.0, after = 0.0;
  for (std::size_t row = 0; row < tr.rows(); ++row) {
    const double d = std::fabs(tr.at(row, meas) - held.trajectory.at(row, meas));
    ASSERT_TRUE(std::isfinite(d)) << "row " << row;
    double& worst = tr.at(row, time) < 1.16 ? before : after;
    worst = std::max(worst, d);
  }
  // at rest the board reads the pull (one physics step behind it: a still arm's pull
  // hardly moves in 1 ms); the impact rings it
  EXPECT_LT(before, 1e-3);
  EXPECT_GT(after, 0.5);
}

// The pressure sensor, fiber sensor and encoder as hardware reach the trial: the plant is
// untouched (its true length), the estimate and the fiber's rate read the hardware.
TEST(ScenarioTest, TheSensorsAsHardwareReachTheTrial) {
  // the shipped drop scenario has them on: the ideal instruments are the comparison
  const std::vector<std::string> base = {"sim.duration_s=1.2", "sensors.pressure.model=\"ideal\"",
                                         "sensors.fiber.model=\"ideal\"",
                                         "sensors.encoder.model=\"ideal\""};
  std::vector<std::string> on = {"sim.duration_s=1.2"};
  on.insert(on.end(), {"sensors.pressure.model=\"pse540\"", "sensors.fiber.model=\"fabric\"",
                       "sensors.encoder.model=\"counts\""});
  const Scenario ideal = load_scenario(kScenario, base), built = load_scenario(kScenario, on);
  EXPECT_TRUE(built.sensing.sensors.pressure_hardware.enabled);
  EXPECT_TRUE(built.sensing.sensors.fiber_hardware.enabled);
  EXPECT_TRUE(built.sensing.sensors.encoder.enabled);
  const TrialResult a = run_trial(load_trial_model(ideal), ideal, 1);
  const TrialResult b = run_trial(load_trial_model(built), built, 1);
  ASSERT_EQ(b.summary.status, "ok") << b.summary.message;
  const Trajectory& ta = a.trajectory;
  const Trajectory& tb = b.trajectory;
  const std::size_t row = ta.rows() / 2;
  // before the drop (1 s) the plant sees the same commands; the estimate does not
  EXPECT_EQ(ta.at(row, ta.column("length_ago_mm")), tb.at(row, tb.column("length_ago_mm")));
  EXPECT_NE(ta.at(row, ta.column("length_est_ago_mm")), tb.at(row, tb.column("length_est_ago_mm")));
}

TEST(ScenarioTest, UnknownKeyInTheFileIsRefusedByName) {
  std::ifstream in(kScenario);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  text += "\n[drop2]\nmass_kg = 0.3\n";
  // keep the relative paths working: write next to the real scenario's models
  const std::string path = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/.unknown_key_test.toml";
  std::ofstream(path) << text;
  const std::string message = error_of({}, path);
  std::remove(path.c_str());
  EXPECT_NE(message.find("drop2.mass_kg"), std::string::npos) << message;
  EXPECT_NE(message.find(".unknown_key_test.toml"), std::string::npos) << message;
}

TEST(ScenarioTest, SyntaxErrorAndMissingFileNameTheFile) {
  const std::string broken = write_temp("broken.toml", "seed = 1\n[sim\ntimestep_s = 0.001\n");
  EXPECT_NE(error_of({}, broken).find("broken.toml:2"), std::string::npos) << error_of({}, broken);
  EXPECT_NE(error_of({}, "/nonexistent/scenario.toml").find("/nonexistent/scenario.toml"),
            std::string::npos);
  EXPECT_NE(error_of({"=3"}).find("--set"), std::string::npos);
  EXPECT_NE(error_of({"novalue"}).find("--set"), std::string::npos);
}

TEST(ScenarioTest, ModelThatFailsToLoadIsNamed) {
  const std::string xml = write_temp("bad_arm.xml", "<mujoco><worldbody><body></mujoco>");
  const std::string message = error_of({"model.file=\"" + xml + "\""});
  EXPECT_NE(message.find("bad_arm.xml"), std::string::npos) << message;
  const std::string no_arm = write_temp("no_arm.xml", "<mujoco><worldbody/></mujoco>");
  const std::string m2 = error_of({"model.file=\"" + no_arm + "\""});
  EXPECT_NE(m2.find("agonist"), std::string::npos) << m2;
}

TEST(ScenarioTest, ParamsFileMissingAFieldIsNamed) {
  // the real agonist file without its a2 line
  std::ifstream in(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/table4_agonist.toml");
  std::string text, line;
  while (std::getline(in, line)) {
    if (line.rfind("a2 ", 0) != 0) text += line + "\n";
  }
  ASSERT_NE(text.find("a3 "), std::string::npos) << "the agonist file moved";
  const std::string params = write_temp("no_a2.toml", text);
  const std::string message = error_of({"model.agonist_params=\"" + params + "\""});
  EXPECT_NE(message.find("no_a2.toml"), std::string::npos) << message;
  EXPECT_NE(message.find("a2"), std::string::npos) << message;
}

}  // namespace
}  // namespace pamsim
