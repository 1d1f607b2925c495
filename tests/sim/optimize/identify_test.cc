// identify_test.cc: `pamsim identify` on a recording made by pamsim from an arm whose
// antagonist's wall is 2.7 mm where the model says 3.0: the wall is recovered within its
// standard error (and the agonist's from a tensile test alone), a parameter the recording
// cannot see (the held ball's mass) is reported as not determined, the held-out recording is
// predicted, a stopped run resumed gives the uninterrupted run's result bit for bit, and
// every bad identification file is one line, exit 2, no database.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/input_error.h"
#include "sim/cli_util.h"
#include "sim/identify_test_arm.h"
#include "pam_actuator/plant_params.h"
#include "pam_actuator/tensile_csv.h"
#include "pam_actuator/tensile_test.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "sim/io/staged_outputs.h"
#include "sim/optimize/identify.h"
#include "sim/optimize/identify_outputs.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;
std::string identify_file(const fs::path& dir) {
  record_arm(dir / "steps.csv", kSteps);
  record_arm(dir / "sine.csv", kSine);
  const std::string text =
      "base = \"" + kArm +
      "\"\noverrides = [\"sim.duration_s=2\"]\nruns = 1\ngenerations = 2\n"
      "population = 6\npolish_iterations = 10\n"
      "[[parameter]]\nkey = \"muscles.antagonist.plant.geometry.wall_thickness_mm\"\nfrom = "
      "2.0\nto = 4.0\n"
      "[[parameter]]\nkey = \"bodies.ball.mass_kg\"\nfrom = 0.1\nto = 0.4\n"
      "[[recording]]\nfile = \"steps.csv\"\nset = ['" +
      kSteps +
      "']\n"
      "[[recording]]\nfile = \"sine.csv\"\nheld_out = true\nset = ['" +
      kSine + "']\n";
  pamsim_test::write_text(dir / "id.toml", text);
  return (dir / "id.toml").string();
}

IdentifyResult run(const IdentifyDefinition& def, const std::string& db_path, bool resume,
                   const std::atomic<bool>* stop = nullptr,
                   std::function<void(const std::string&, std::int64_t)> progress = nullptr) {
  IdentifyDb db =
      resume ? IdentifyDb::open_to_resume(db_path, def) : IdentifyDb::create(db_path, def);
  IdentifyRunOptions o;
  o.threads = 2;
  o.stop = stop;
  o.on_progress = std::move(progress);
  return run_identify(def, db, o);
}

TEST(IdentifyTest, RecoversTheWallAndSaysWhatTheRecordingCannotSee) {
  const fs::path dir = pamsim_test::fresh_dir("identify_wall");
  const IdentifyDefinition def = load_identify_definition(identify_file(dir));
  const IdentifyResult r = run(def, (dir / "id.db").string(), false);
  ASSERT_FALSE(r.interrupted);
  ASSERT_EQ(r.parameters.size(), 2u);
  const IdentifiedParameter& wall = r.parameters[0];
  EXPECT_TRUE(wall.identifiable);
  EXPECT_NEAR(wall.value, 2.7, std::max(3 * wall.std_error, 0.01)) << "+- " << wall.std_error;
  EXPECT_GT(wall.std_error, 0.0);
  EXPECT_EQ(wall.start, 3.0) << "plant_antagonist.toml's";
  EXPECT_EQ(r.parameters[1].start, 0.2) << "the model's ball";
  EXPECT_FALSE(r.parameters[1].identifiable) << "the ball is held away from the arm";
  EXPECT_TRUE(std::isnan(r.parameters[1].std_error));
  ASSERT_EQ(r.fits.size(), 2u);
  for (const ChannelFit& f : r.fits) {
    EXPECT_LT(f.rmse_after, 0.1 * f.rmse_before)
        << f.recording << (f.held_out ? " (held out)" : "");
  }
  EXPECT_TRUE(r.fits[1].held_out);
  EXPECT_LE(r.cost_final, r.cost_global);
}

// A tensile test alone: the agonist's wall from its plant's forces at the recorded pressures
// and lengths (no trial runs).
TEST(IdentifyTest, ATensileTestAloneGivesThePlantsWall) {
  const fs::path dir = pamsim_test::fresh_dir("identify_tensile");
  AvbdlParams truth =
      load_plant_params(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_agonist.toml").avbdl;
  truth.wall_thickness_m = 2.2e-3;
  TensileTestOptions test;
  test.pressures_mpa = {0.2, 0.4, 0.6};
  test.max_deformation_mm = 10.0;
  test.noise_force_n = 0.5;
  test.seed = 3;
  pamsim_test::write_text(dir / "tensile.csv", tensile_rows_to_csv(run_tensile_test(truth, test)));
  pamsim_test::write_text(
      dir / "id.toml",
      "base = \"" + kArm +
          "\"\nruns = 1\ngenerations = 2\npopulation = 5\npolish_iterations = 10\n"
          "[[parameter]]\nkey = \"muscles.agonist.plant.geometry.wall_thickness_mm\"\nfrom = "
          "1.5\nto = 3.0\n"
          "[[tensile]]\nmuscle = \"agonist\"\nfile = \"tensile.csv\"\n");
  const IdentifyDefinition def = load_identify_definition((dir / "id.toml").string());
  const IdentifyResult r = run(def, (dir / "id.db").string(), false);
  ASSERT_EQ(r.parameters.size(), 1u);
  EXPECT_NEAR(r.parameters[0].value, 2.2, std::max(3 * r.parameters[0].std_error, 0.005));
  ASSERT_EQ(r.fits.size(), 1u);
  EXPECT_EQ(r.fits[0].recording, "tensile_agonist");
  EXPECT_LT(r.fits[0].rmse_after, 0.7) << "about the 0.5 N noise";
  EXPECT_GT(r.fits[0].rmse_before, 3 * r.fits[0].rmse_after);
  // the outputs: the plant file with the identified wall, a plant file pamsim reads
  {
    StagedOutputs staged((dir / "out").string(), kIdentifyOutputs);
    write_identify_outputs(def, r, staged, false);
    staged.publish();
  }
  const PlantParams written = load_plant_params((dir / "out" / "plant_agonist.toml").string());
  EXPECT_DOUBLE_EQ(written.avbdl.wall_thickness_m, r.parameters[0].value * 1e-3);
  EXPECT_FALSE(fs::exists(dir / "out" / "plant_antagonist.toml")) << "no field of it identified";
  EXPECT_FALSE(fs::exists(dir / "out" / "pneumatics.toml"));
  const Scenario identified = load_scenario((dir / "out" / "identified.toml").string());
  for (const MuscleSpec& m : identified.muscles) {
    if (m.actuator == "agonist") {
      EXPECT_DOUBLE_EQ(m.plant.wall_thickness_m, written.avbdl.wall_thickness_m);
    }
  }
}

// A sensor's gain, offset and delay: the recorded antagonist force is 1.05 F(t - 20 ms) + 2 N
// of the model's own arm.
TEST(IdentifyTest, ASensorsGainOffsetAndDelayAreParametersToo) {
  const fs::path dir = pamsim_test::fresh_dir("identify_sensor");
  const Scenario sc = load_scenario(kArm, {"sim.duration_s=2", "seed=7", kSine});
  const TrialResult t = run_trial(load_trial_model(sc), sc, sc.seed, true);
  const std::size_t force = t.trajectory.column("force_meas_anta_N");
  std::string csv = "time_s,force_meas_anta_N\n";
  for (std::size_t row = 2; row < t.trajectory.rows(); row += 2) {  // 100 Hz log, 20 ms = 2 rows
    csv += format_shortest(t.trajectory.at(row, 0)) + "," +
           format_shortest(1.05 * t.trajectory.at(row - 2, force) + 2.0) + "\n";
  }
  pamsim_test::write_text(dir / "sine.csv", csv);
  pamsim_test::write_text(
      dir / "id.toml",
      "base = \"" + kArm +
          "\"\noverrides = [\"sim.duration_s=2\"]\nruns = 1\ngenerations = 3\n"
          "population = 6\npolish_iterations = 20\n"
          "[[parameter]]\nkey = \"channel.force_meas_anta_N.gain\"\nfrom = 0.8\nto = 1.2\n"
          "[[parameter]]\nkey = \"channel.force_meas_anta_N.offset\"\nfrom = -5.0\nto = 5.0\n"
          "[[parameter]]\nkey = \"channel.force_meas_anta_N.delay_ms\"\nfrom = 0.0\nto = 50.0\n"
          "[[recording]]\nfile = \"sine.csv\"\nset = ['" +
          kSine + "']\n");
  const IdentifyDefinition def = load_identify_definition((dir / "id.toml").string());
  const IdentifyResult r = run(def, (dir / "id.db").string(), false);
  ASSERT_EQ(r.parameters.size(), 3u);
  EXPECT_EQ(r.parameters[0].start, 1.0) << "a sensor starts ideal";
  EXPECT_NEAR(r.parameters[0].value, 1.05, 0.005);
  EXPECT_NEAR(r.parameters[1].value, 2.0, 0.1);
  EXPECT_NEAR(r.parameters[2].value, 20.0, 1.0);
  for (const IdentifiedParameter& p : r.parameters) EXPECT_TRUE(p.identifiable) << p.parameter.key;
  EXPECT_LT(r.fits[0].rmse_after, 0.1 * r.fits[0].rmse_before) << "down to the gauge noise";
  // a sensor's parameters are no scenario key: the trials' overrides do not hold them
  EXPECT_EQ(def.overrides_at(std::vector<double>{1.0, 0.0, 0.0}), def.overrides);
}

// A resume after a file the scenario reads changed is refused: its stored points belong to
// the model as it was.
TEST(IdentifyTest, AResumeAfterAnInputFileChangedIsRefused) {
  const fs::path dir = pamsim_test::fresh_dir("identify_inputs");
  fs::copy_file(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_antagonist.toml",
                dir / "plant_antagonist.toml");
  const std::string source_plant =
      "plant = \"" + std::string(PAMSIM_SOURCE_DIR) + "/models/pams/plant_antagonist.toml\"";
  const std::string base =
      pamsim_test::scenario_variant(dir, "reaching.toml", source_plant,
                                    "plant = \"" + (dir / "plant_antagonist.toml").string() + "\"");
  record_arm(dir / "steps.csv", kSteps);
  pamsim_test::write_text(
      dir / "id.toml",
      "base = \"" + base +
          "\"\noverrides = [\"sim.duration_s=2\"]\nruns = 1\ngenerations = 0\n"
          "polish_iterations = 0\n"
          "[[parameter]]\nkey = \"joints.shoulder.damping_N_m_s_per_rad\"\nfrom = 0.05\nto = 0.2\n"
          "[[recording]]\nfile = \"steps.csv\"\nset = ['" +
          kSteps + "']\n");
  const IdentifyDefinition def = load_identify_definition((dir / "id.toml").string());
  const std::string db = (dir / "id.db").string();
  { IdentifyDb made = IdentifyDb::create(db, def); }
  { IdentifyDb same = IdentifyDb::open_to_resume(db, def); }  // nothing changed
  std::ofstream(dir / "plant_antagonist.toml", std::ios::app) << "# edited\n";
  try {
    IdentifyDb::open_to_resume(db, def);
    ADD_FAILURE() << "resumed on a changed plant file";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("muscles.antagonist.plant"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("changed since this identification began"),
              std::string::npos)
        << e.what();
  }
}

TEST(IdentifyTest, AStoppedRunResumedIsTheUninterruptedOne) {
  const fs::path dir = pamsim_test::fresh_dir("identify_resume");
  const IdentifyDefinition def = load_identify_definition(identify_file(dir));
  const IdentifyResult whole = run(def, (dir / "whole.db").string(), false);
  std::atomic<bool> stop{false};
  const IdentifyResult part =
      run(def, (dir / "part.db").string(), false, &stop, [&](const std::string&, std::int64_t n) {
        if (n == 7) stop = true;
      });
  ASSERT_TRUE(part.interrupted);
  const IdentifyResult resumed = run(def, (dir / "part.db").string(), true);
  ASSERT_FALSE(resumed.interrupted);
  EXPECT_EQ(resumed.unit, whole.unit) << "bit for bit";
  EXPECT_EQ(resumed.parameters[0].std_error, whole.parameters[0].std_error);
  EXPECT_LT(resumed.simulated, whole.simulated) << "the stored points are not simulated again";
  EXPECT_THROW(run(def, (dir / "whole.db").string(), false), InputError) << "it exists";
}

// The shipped example stays a valid identification: its recordings, tensile test and keys.
TEST(IdentifyTest, TheShippedExampleLoads) {
  const IdentifyDefinition def =
      load_identify_definition(std::string(PAMSIM_SOURCE_DIR) + "/examples/identify/identify.toml");
  EXPECT_EQ(def.parameters.size(), 5u);
  EXPECT_EQ(def.candidates.size(), 4u) << "ball_drop, reflex_drop, slow_ramp, fast_steps";
  ASSERT_EQ(def.recordings.size(), 3u);
  EXPECT_TRUE(def.recordings[2].held_out);
  EXPECT_EQ(def.recordings[0].data.channels.size(), 5u);
  EXPECT_EQ(def.recordings[1].data.channels.size(), 2u) << "sine.csv: angle and one force";
  ASSERT_EQ(def.tensile.size(), 1u);
  EXPECT_EQ(def.tensile[0].muscle, "agonist");
}

// A valve's field starts where the scenario's valve runs: the pneumatics file's [regulator]
// (models/pams/pneumatics.toml: 10 ms, 20 ms, 380 kPa), or the scenario's own value.
TEST(IdentifyTest, AValvesFieldStartsAtTheValueTheValveRunsWith) {
  IdentifyDefinition def =
      load_identify_definition(std::string(PAMSIM_SOURCE_DIR) + "/examples/identify/identify.toml");
  def.parameters = {{"valve.dead_time_ms", 1.0, 20.0, false},
                    {"valve.valve_time_constant_ms", 4.0, 60.0, true},
                    {"valve.proportional_band_kPa", 200.0, 800.0, true}};
  def.channel_parameters.assign(3, ChannelParameter{});
  EXPECT_EQ(start_values(def), (std::vector<double>{10.0, 20.0, 380.0}));
  def.overrides.push_back("valve.dead_time_ms=6.3");
  EXPECT_EQ(start_values(def)[0], 6.3);
}

// clang-format off
TEST(IdentifyTest, BadFilesAreOneLineExitTwoAndNoDatabase) {
  const fs::path dir = pamsim_test::fresh_dir("identify_bad");
  const std::string good = pamsim_test::read_file(identify_file(dir));
  pamsim_test::write_text(dir / "nan.csv", "time_s,angle_deg\n0,1\n0.5,nan\n");
  pamsim_test::write_text(dir / "back.csv", "time_s,angle_deg\n0,1\n0.5,2\n0.4,3\n");
  pamsim_test::write_text(dir / "notime.csv", "t,angle_deg\n0,1\n0.5,2\n");
  pamsim_test::write_text(dir / "rad.csv", "time_s,angle_rad\n0,1\n0.5,2\n");
  pamsim_test::write_text(dir / "tensile.csv", "pressure_MPa,deformation_mm,force_N,length_mm\n"
                                               "0.4,0,10,150\n0.4,2.5,20,152.5\n");
  auto with = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    t.replace(t.find(from), from.size(), to);
    return t;
  };
  for (const auto& [text, says] : std::vector<std::pair<std::string, std::string>>{
           {with("file = \"steps.csv\"", "file = \"notime.csv\""), "no time_s column"},
           {with("file = \"steps.csv\"", "file = \"back.csv\""), "time_s must increase strictly"},
           {with("file = \"steps.csv\"", "file = \"nan.csv\""), "must be a finite number or empty"},
           {with("file = \"steps.csv\"", "file = \"rad.csv\""), "channel angle_rad is not a column pamsim logs"},
           {with("file = \"steps.csv\"", "file = \"steps.csv\"\nchannels = [\"force_meas_ago_N\"]"), "names force_meas_ago_N, which"},
           {with("file = \"steps.csv\"", "file = \"steps.csv\"\nchannels = [\"angle_deg\", \"angle_deg\"]"), "names angle_deg twice"},
           {with("from = 2.0\nto = 4.0", "from = -2.0\nto = 4.0"), "wall_thickness_mm: must be in [0, inf) mm, got -2"},
           {with("key = \"bodies.ball.mass_kg\"", "key = \"sensors.colour\""), "sensors.colour is not a known key"},
           {with("from = 0.1\nto = 0.4", "from = 0.4\nto = 0.4"), "parameter[1]"},
           {with("file = \"steps.csv\"", "file = \"steps.csv\"\nheld_out = true"), "needs at least one [[recording]] that is not held_out"},
           {with("file = \"steps.csv\"", "file = \"missing.csv\""), "missing.csv"},
           {with(kArm, kArm + std::string(300, 'l')), "base cannot be resolved (File name too long)"},
           {with("overrides = [\"sim.duration_s=2\"]", "overrides = [\"sim.duration_s=1\"]"), "the recording lasts 1.98 s, its scenario 1 s"},
           {good + "[[tensile]]\nmuscle = \"agonist\"\nfile = \"t.csv\"\n", "tensile[0].file"},
           {with("key = \"bodies.ball.mass_kg\"", "key = \"channel.angle_rad.offset\""), "no recording matches angle_rad"},
           {with("key = \"bodies.ball.mass_kg\"", "key = \"channel.angle_deg.scale\""), "channel.<column>.offset, .gain or .delay_ms"},
           {with("key = \"bodies.ball.mass_kg\"\nfrom = 0.1", "key = \"channel.angle_deg.gain\"\nfrom = -0.1"), "a gain's range must be above 0"},
           {with("key = \"bodies.ball.mass_kg\"\nfrom = 0.1\nto = 0.4", "key = \"channel.angle_deg.delay_ms\"\nfrom = 0.0\nto = 2000.0"), "within [0, 1000] ms"},
           {good + "[[tensile]]\nmuscle = \"elbow\"\nfile = \"steps.csv\"\n", "tensile[0].file"},
           {"interval = 1.5\n" + good, "interval must be in (0, 1), got 1.5"},
           {"interval = 0\n" + good, "interval must be in (0, 1), got 0"},
           {with("file = \"steps.csv\"", "file = \"steps.csv\"\nnoise = { angle_deg = 0 }"),
            "recording[0].noise.angle_deg must be a noise floor > 0"},
           {with("file = \"steps.csv\"", "file = \"steps.csv\"\nnoise = { angle_deg = -0.1 }"),
            "recording[0].noise.angle_deg must be a noise floor > 0"},
           {with("file = \"steps.csv\"", "file = \"steps.csv\"\nnoise = { omega_deg_s = 1 }"),
            "recording[0].noise.omega_deg_s is not a channel the recording is matched on"},
           {good + "[[tensile]]\nmuscle = \"elbow\"\nfile = \"tensile.csv\"\n",
            "tensile[0].muscle \"elbow\" is not a muscle of the base scenario (it has agonist, antagonist)"}}) {
    pamsim_test::expect_file_refused(dir, "identify", text, "", says);
  }
}
// clang-format on

}  // namespace
}  // namespace pamsim
