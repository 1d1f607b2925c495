// cli_run_test.cc: `pamsim run` and `pamsim calibrate` as a user runs them: outputs appear
// whole, bad input gives one line on stderr, a non-zero exit, and no output at all.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "sim/cli_util.h"

namespace {

namespace fs = std::filesystem;

using pamsim_test::CliResult;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::run_pamsim;
using pamsim_test::write_text;

TEST(CliRunTest, RunWritesTrajectorySummaryAndPlot) {
  const fs::path out = fresh_dir("run_ok");
  const CliResult r =
      run_pamsim("run scenarios/drop_mass.toml --set sim.duration_s=1.5 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"trajectory.csv", "summary.json", "angle.png"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  std::ifstream in(out / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  EXPECT_EQ(s["status"], "ok");
  for (const char* key :
       {"seed", "start_angle_deg", "min_angle_deg", "peak_drop_deg", "final_angle_deg",
        "impact_time_s", "steps", "sim_time_s", "reflex_triggers_ago", "reflex_triggers_anta",
        "first_trigger_time_s", "mistrips", "recovery_time_s", "length_est_rmse_mm",
        "length_est_max_error_mm"}) {
    EXPECT_TRUE(s.contains(key)) << key;
  }
  EXPECT_EQ(s["steps"], 1500);
  // the timing, which varies from run to run, is in provenance.json, not in the summary
  EXPECT_FALSE(s.contains("wall_time_s"));
  EXPECT_FALSE(s.contains("realtime_factor"));
  std::ifstream p(out / "provenance.json");
  const nlohmann::json prov = nlohmann::json::parse(p);
  ASSERT_EQ(prov["trials"].size(), 1u);
  EXPECT_GT(prov["trials"][0]["wall_time_s"].get<double>(), 0.0);
  EXPECT_GT(prov["trials"][0]["realtime_factor"].get<double>(), 0.0);
  // no temp file left beside the outputs
  for (const auto& e : fs::directory_iterator(out)) {
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  }
}

TEST(CliRunTest, TrialsWriteEachTrialAndTheAggregate) {
  const fs::path out = fresh_dir("run_trials");
  const CliResult r = run_pamsim(
      "run scenarios/drop_mass.toml --set sim.duration_s=1.3 --trials 3 "
      "--threads 2 --out " +
      out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f :
       {"summary.json", "angle_band.png", "trial_0000/trajectory.csv", "trial_0002/summary.json"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  std::ifstream in(out / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(in);
  EXPECT_EQ(s["trials"], 3);
  EXPECT_TRUE(s["metrics"]["min_angle_deg"].contains("mean"));
}

TEST(CliRunTest, BadInputIsOneLineNonZeroAndWritesNothing) {
  // (two levels: no folder on the way is left behind either)
  const fs::path out = fresh_dir("run_bad") / "new" / "out";
  for (const std::string args :
       {"run scenarios/missing.toml", "run scenarios/drop_mass.toml --set reflex.v_thr_mm_s=-1",
        "run scenarios/drop_mass.toml --set sim.timestep_s=nan",
        "run scenarios/drop_mass.toml --set nosuch.key=1",
        "run scenarios/drop_mass.toml --set model.file=\\\"/nonexistent.xml\\\"",
        "run scenarios/drop_mass.toml --trials 0", "run scenarios/drop_mass.toml --threads -1",
        "run"}) {
    const CliResult r = run_pamsim(args + " --out " + out.string());
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("pamsim: ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(out.parent_path())) << args;
  }
}

// An --out the file system cannot hold (a name too long, a folder through a file): bad input,
// exit 2, one line naming the path
TEST(CliRunTest, AnOutFolderThatCannotBeIsOneLineExitTwo) {
  const fs::path dir = fresh_dir("run_bad_out");
  write_text(dir / "a_file", "x\n");
  for (const fs::path& out : {dir / std::string(300, 'a'), dir / "a_file" / "out"}) {
    const CliResult r = run_pamsim("run scenarios/drop_mass.toml --no-plot --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << out << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(dir.string()), std::string::npos) << r.err;
  }
}

// `pamsim run SCENARIO --set ...` for each case: exit 2, one line naming the key, and
// nothing written (not even the output folder's parent)
struct BadSet {
  std::string set, key;
};
void expect_refused_writing_nothing(const std::string& scenario, const std::string& dir,
                                    const std::vector<BadSet>& cases) {
  const fs::path out = fresh_dir(dir) / "new" / "out";
  for (const BadSet& c : cases) {
    const CliResult r =
        run_pamsim("run scenarios/" + scenario + " " + c.set + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.set;
    EXPECT_EQ(line_count(r.err), 1) << c.set << ": " << r.err;
    EXPECT_NE(r.err.find(c.key), std::string::npos) << c.set << ": " << r.err;
    EXPECT_FALSE(fs::exists(out.parent_path())) << c.set;
  }
}

// The hardware's error sources: a negative creep constant, a tolerance over 100 %,
// a line diameter of zero, a loss factor of 1, a bladder relaxing in negative time.
TEST(CliRunTest, BadHardwareKeysAreOneLineExitTwoAndWriteNothing) {
  expect_refused_writing_nothing(
      "drop_mass.toml", "run_bad_hardware",
      {{"--set 'sensors.gauge.board.creep_weights=[-0.02]' "
        "--set 'sensors.gauge.board.creep_times_s=[60]'",
        "sensors.gauge.board.creep_weights[0]"},
       {"--set 'sensors.fiber.creep_weights=[-0.02]' --set 'sensors.fiber.creep_times_s=[60]'",
        "sensors.fiber.creep_weights[0]"},
       {"--set sensors.gauge.tolerance_pct=150", "sensors.gauge.tolerance_pct"},
       {"--set muscles.agonist.line_diameter_mm=0 --set muscles.agonist.line_modulus_MPa=2500",
        "muscles.agonist.line_diameter_mm"},
       {"--set sensors.gauge.board.loss_factor=1", "sensors.gauge.board.loss_factor"},
       {"--set 'muscles.agonist.plant.bladder.relaxation_times_s=[-1]' "
        "--set 'muscles.agonist.plant.bladder.relaxation_weights=[0.07]'",
        "muscles.agonist.plant.bladder.relaxation_times_s: [0] must be in (0, inf) s, got -1"}});
}

// The tension (Ib) reflex and reflex pairs: an Ib threshold below zero, a reflex pair naming
// a muscle twice.
TEST(CliRunTest, BadTensionReflexKeysAreOneLineExitTwoAndWriteNothing) {
  expect_refused_writing_nothing(
      "drop_mass_heavy_ia_ib.toml", "run_bad_tension_reflex",
      {{"--set reflex.ib.f_thr_N=-1", "reflex.ib.f_thr_N must be in (0, inf) N, got -1"},
       {"--set 'reflex.pairs=[[\"agonist\", \"agonist\"]]'", "reflex.pairs"}});
}

// A run that fails after its first output (here a full disk: a file-size limit with SIGXFSZ
// ignored) leaves the folder of an earlier run exactly as it was, and nothing beside it: its
// CSV and JSON are not replaced before the failure, which would leave a mix of two runs.
TEST(CliRunTest, ARunThatFailsHalfWayLeavesTheEarlierOutputsAsTheyWere) {
  const fs::path dir = fresh_dir("run_staged");
  const fs::path out = dir / "out";
  const std::string run =
      "run scenarios/drop_mass.toml --set sim.duration_s=1.3 --out " + out.string();
  ASSERT_EQ(run_pamsim(run).exit_code, 0);
  const auto before = pamsim_test::folder_snapshot(dir);
  const CliResult full = run_pamsim(run + " --set seed=7 --force",
                                    "bash -c 'trap \"\" XFSZ; ulimit -f 32; exec \"$0\" \"$@\"'");
  EXPECT_NE(full.exit_code, 0);
  EXPECT_EQ(line_count(full.err), 1) << full.err;
  EXPECT_EQ(pamsim_test::folder_snapshot(dir), before);

  // a run of fewer trials replaces the whole set: no trial folder of the earlier run is left
  ASSERT_EQ(run_pamsim(run + " --trials 3 --force").exit_code, 0) << "3 trials";
  ASSERT_EQ(run_pamsim(run + " --trials 2 --force").exit_code, 0) << "2 trials";
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(out)) names.insert(e.path().filename());
  EXPECT_EQ(names, (std::set<std::string>{"angle_band.png", "provenance.json", "scenario.toml",
                                          "summary.json", "trial_0000", "trial_0001"}));
}

TEST(CliRunTest, CalibrateReproducesTheShippedCalibration) {
  const fs::path out = fresh_dir("calib");
  fs::create_directories(out);
  // the physical plants' lines and the ideal plant's (drop_mass_ideal.toml)
  for (const auto& [args, shipped] :
       {std::pair<std::string, std::string>{"scenarios/drop_mass_passive.toml",
                                            "arm_2pam_plant_calibration.toml"},
        {"scenarios/drop_mass_ideal.toml", "arm_2pam_calibration.toml"}}) {
    SCOPED_TRACE(shipped);
    const CliResult r = run_pamsim("calibrate " + args + " -o " + (out / shipped).string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream a(out / shipped), b(std::string(PAMSIM_SOURCE_DIR) + "/models/" + shipped);
    std::string la, lb;
    int lines = 0;
    // same numbers (the provenance line names the scenario path)
    while (std::getline(a, la) && std::getline(b, lb)) {
      ++lines;
      if (la.rfind("written_by", 0) == 0) continue;
      EXPECT_EQ(la, lb);
    }
    EXPECT_GT(lines, 8);
  }
  const CliResult bad = run_pamsim("calibrate scenarios/drop_mass_passive.toml --angle-deg 95 -o " +
                                   (out / "d.toml").string());
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_FALSE(fs::exists(out / "d.toml"));
}

}  // namespace

namespace {

// A plant changed after the lines were calibrated moves the start (a 1.5 mm wall: -36 to
// -32.9 deg); the run says so in one line and names the way to keep the start, which holds.
TEST(CliRunTest, AStartTheCalibrationNoLongerHoldsIsNamed) {
  const fs::path dir = fresh_dir("run_start_moved");
  const std::string run = "run scenarios/drop_mass.toml --no-plot --out ";
  const std::string wall = " --set muscles.agonist.plant.geometry.wall_thickness_mm=1.5";
  const CliResult moved = run_pamsim(run + (dir / "a").string() + pamsim_test::kShortDrop + wall);
  ASSERT_EQ(moved.exit_code, 0) << moved.err;
  EXPECT_NE(moved.err.find("warning: the arm starts at -3"), std::string::npos) << moved.err;
  EXPECT_NE(moved.err.find("not the -36.0 deg"), std::string::npos) << moved.err;
  EXPECT_NE(moved.err.find("line = \"equilibrium\""), std::string::npos) << moved.err;
  const CliResult held = run_pamsim(run + (dir / "b").string() + pamsim_test::kShortDrop + wall +
                                    " muscles.agonist.line=\\\"equilibrium\\\"");
  ASSERT_EQ(held.exit_code, 0) << held.err;
  EXPECT_EQ(held.err.find("warning"), std::string::npos) << held.err;
  const CliResult shipped = run_pamsim(run + (dir / "c").string() + pamsim_test::kShortDrop);
  EXPECT_EQ(shipped.err.find("warning"), std::string::npos) << shipped.err;
}

}  // namespace
