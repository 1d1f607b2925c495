// cli_reproduce_test.cc: outputs that can be traced and reproduced, and a command line that
// can be scripted: a run's folder records what made it and `run --from` rebuilds
// it byte for byte; `replay` runs a sweep's trial again and equals its stored row; an earlier
// run's outputs are not replaced without --force; the default folder names the overrides;
// --no-plot, and a run without gnuplot on PATH, still succeed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/sweep/results_db.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::read_file;
using pamsim_test::run_pamsim;

const std::string kShort = pamsim_test::kShortDrop;

nlohmann::json json_of(const fs::path& path) { return nlohmann::json::parse(read_file(path)); }

TEST(CliReproduceTest, ARunFromItsFolderWritesByteIdenticalOutputs) {
  const fs::path dir = fresh_dir("reproduce_from");
  for (const int trials : {1, 2}) {
    const fs::path a = dir / ("a" + std::to_string(trials));
    const fs::path b = dir / ("b" + std::to_string(trials));
    const CliResult first =
        run_pamsim("run scenarios/drop_mass.toml --no-plot --trials " + std::to_string(trials) +
                   " --out " + a.string() + kShort + " reflex.v_thr_mm_s=55");
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const CliResult again =
        run_pamsim("run --from " + a.string() + " --no-plot --out " + b.string());
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.out, first.out);  // the summary printed
    const std::vector<std::string> files =
        trials == 1 ? std::vector<std::string>{"trajectory.csv", "summary.json"}
                    : std::vector<std::string>{
                          "summary.json", "trial_0000/trajectory.csv", "trial_0000/summary.json",
                          "trial_0001/trajectory.csv", "trial_0001/summary.json"};
    for (const std::string& f : files) {
      ASSERT_TRUE(fs::exists(a / f)) << f;
      EXPECT_EQ(read_file(a / f), read_file(b / f)) << f << " of " << trials << " trial(s)";
    }
    // the rerun's provenance says where it came from and keeps the first run's scenario file
    const nlohmann::json p = json_of(b / "provenance.json");
    EXPECT_EQ(p["from"], a.string());
    EXPECT_EQ(p["scenario_file"], "scenarios/drop_mass.toml");
    EXPECT_EQ(p["seeds"].size(), static_cast<std::size_t>(trials));
  }
  // the saved scenario holds the override, and the defaults as comments
  const std::string saved = read_file(dir / "a1" / "scenario.toml");
  EXPECT_NE(saved.find("v_thr_mm_s = 55\n"), std::string::npos) << saved;
  EXPECT_NE(saved.find("# sim.max_steps = 1e+07\n"), std::string::npos) << saved;
  // and runs as a scenario file itself, from anywhere
  const CliResult direct = run_pamsim("run " + (dir / "a1" / "scenario.toml").string() +
                                      " --no-plot --out " + (dir / "c").string());
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  EXPECT_EQ(read_file(dir / "c" / "trajectory.csv"), read_file(dir / "a1" / "trajectory.csv"));
}

// The inputs are fingerprinted: a file changed since the run is named when it runs again.
TEST(CliReproduceTest, AnInputChangedSinceTheRunIsNamedWhenItRunsAgain) {
  const fs::path dir = fresh_dir("reproduce_inputs");
  const std::string calibration =
      std::string(PAMSIM_SOURCE_DIR) + "/models/arm_2pam_plant_calibration.toml";
  fs::copy_file(calibration, dir / "cal.toml");
  const std::string own = pamsim_test::scenario_variant(dir, "drop_mass.toml", calibration,
                                                        (dir / "cal.toml").string());
  ASSERT_EQ(
      run_pamsim("run " + own + " --no-plot --out " + (dir / "own").string() + kShort).exit_code,
      0);
  const nlohmann::json inputs = json_of(dir / "own" / "provenance.json")["inputs"];
  std::set<std::string> keys;
  for (const auto& f : inputs) keys.insert(f["key"].get<std::string>());
  EXPECT_TRUE(keys.count("model.file") && keys.count("model.calibration")) << inputs.dump();
  EXPECT_EQ(run_pamsim("run --from " + (dir / "own").string() + " --no-plot").err.find("changed"),
            std::string::npos);
  pamsim_test::write_text(dir / "cal.toml", read_file(dir / "cal.toml") + "# edited\n");
  const CliResult changed =
      run_pamsim("run --from " + (dir / "own").string() + " --no-plot --force");
  EXPECT_EQ(changed.exit_code, 0) << changed.err;
  EXPECT_NE(changed.err.find("model.calibration (" + (dir / "cal.toml").string() + ") changed"),
            std::string::npos)
      << changed.err;

  // an input path that is no file (a hand-edited provenance.json) is named, not read
  nlohmann::json edited = json_of(dir / "own" / "provenance.json");
  edited["inputs"][0]["path"] = "/dev/zero";
  pamsim_test::write_text(dir / "own" / "provenance.json", edited.dump(2));
  const CliResult device =
      run_pamsim("run --from " + (dir / "own").string() + " --no-plot --force");
  EXPECT_EQ(device.exit_code, 0) << device.err;
  EXPECT_NE(device.err.find("(/dev/zero) is gone or not a readable file"), std::string::npos)
      << device.err;
}

TEST(CliReproduceTest, BadFromFoldersAreRefused) {
  const fs::path dir = fresh_dir("reproduce_bad");
  EXPECT_EQ(run_pamsim("run --from " + (dir / "nothing").string()).exit_code, 2);
  const CliResult both = run_pamsim("run scenarios/drop_mass.toml --from " + dir.string());
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("--from"), std::string::npos) << both.err;
  fs::create_directories(dir / "broken");
  pamsim_test::write_text(dir / "broken" / "provenance.json", "{\"format\": \"something\"}");
  const CliResult broken = run_pamsim("run --from " + (dir / "broken").string());
  EXPECT_EQ(broken.exit_code, 2);
  EXPECT_NE(broken.err.find("not a pamsim provenance file"), std::string::npos) << broken.err;
}

TEST(CliReproduceTest, ProvenanceRecordsWhatMadeTheRun) {
  const fs::path out = fresh_dir("reproduce_provenance") / "run";
  const CliResult r =
      run_pamsim("run scenarios/drop_mass.toml --no-plot --trials 3 --threads 2 --out " +
                 out.string() + kShort);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json p = json_of(out / "provenance.json");
  EXPECT_EQ(p["format"], "pamsim-provenance-1");
  EXPECT_EQ(p["command"], "run");
  EXPECT_EQ(p["scenario_file"], "scenarios/drop_mass.toml");
  EXPECT_EQ(p["overrides"], (std::vector<std::string>{"sim.duration_s=1.5", "drop.time_s=0.3"}));
  EXPECT_EQ(p["seeds"], (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(p["threads"], 2);
  EXPECT_EQ(p["command_line"][1], "run");
  EXPECT_EQ(p["build"]["mujoco_version"], "2.2.2");
  EXPECT_EQ(p["build"]["sundials_version"].get<std::string>().rfind("6.4", 0), 0u);
  EXPECT_EQ(p["build"]["pamsim_version"], PAMSIM_VERSION);
  EXPECT_FALSE(p["build"]["git_commit"].get<std::string>().empty());
  EXPECT_GT(p["wall_time_s"].get<double>(), 0.0);
  ASSERT_EQ(p["trials"].size(), 3u);
  // the aggregate gives the spread and the 95 % interval of the mean
  const nlohmann::json peak = json_of(out / "summary.json")["metrics"]["peak_drop_deg"];
  EXPECT_EQ(peak["count"], 3);
  EXPECT_LE(peak["ci95_low"].get<double>(), peak["mean"].get<double>());
  EXPECT_GE(peak["ci95_high"].get<double>(), peak["mean"].get<double>());
  EXPECT_GE(peak["sd"].get<double>(), 0.0);
}

TEST(CliReproduceTest, AnEarlierRunsOutputsAreReplacedOnlyWithForce) {
  const fs::path dir = fresh_dir("reproduce_force");
  const std::string run =
      "run scenarios/drop_mass.toml --no-plot --out " + (dir / "out").string() + kShort;
  ASSERT_EQ(run_pamsim(run).exit_code, 0);
  pamsim_test::write_text(dir / "out" / "notes.txt", "the user's own file");
  const auto before = pamsim_test::folder_snapshot(dir);
  const CliResult refused = run_pamsim(run + " seed=5");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(line_count(refused.err), 1) << refused.err;
  EXPECT_NE(refused.err.find("add --force"), std::string::npos) << refused.err;
  EXPECT_EQ(pamsim_test::folder_snapshot(dir), before);
  // a folder holding only the user's files is not an earlier run
  const CliResult beside = run_pamsim("run scenarios/drop_mass.toml --no-plot --out " +
                                      (dir / "other").string() + kShort);
  ASSERT_EQ(beside.exit_code, 0) << beside.err;
  const CliResult forced = run_pamsim(run + " seed=5 --force");
  ASSERT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_EQ(json_of(dir / "out" / "summary.json")["seed"], 5);
  EXPECT_EQ(read_file(dir / "out" / "notes.txt"), "the user's own file");
}

TEST(CliReproduceTest, TheDefaultFolderNamesTheScenarioAndTheOverrides) {
  const fs::path dir = fresh_dir("reproduce_default_out");
  const std::string scenario = std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml";
  const CliResult r = run_pamsim("run " + scenario + " --no-plot" + kShort + " reflex.mode=latch",
                                 "cd " + dir.string() + " &&");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "renders" / "drop_mass__duration_s-1.5__time_s-0.3__mode-latch" /
                         "summary.json"))
      << r.err;
}

TEST(CliReproduceTest, NoPlotAndNoGnuplotStillRun) {
  const fs::path dir = fresh_dir("reproduce_no_plot");
  const CliResult quiet =
      run_pamsim("run scenarios/drop_mass.toml --no-plot --out " + (dir / "a").string() + kShort);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_FALSE(fs::exists(dir / "a" / "angle.png"));
  EXPECT_EQ(quiet.err.find("gnuplot"), std::string::npos) << quiet.err;
  // no gnuplot on PATH: the run succeeds and says the plots were skipped
  const CliResult without =
      run_pamsim("run scenarios/drop_mass.toml --out " + (dir / "b").string() + kShort,
                 "env PATH=" + dir.string());
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_TRUE(fs::exists(dir / "b" / "trajectory.csv"));
  EXPECT_FALSE(fs::exists(dir / "b" / "angle.png"));
  EXPECT_NE(without.err.find("gnuplot not found on PATH: plots skipped"), std::string::npos)
      << without.err;
}

// The row of `trial` in an exported sweep CSV, by column name (empty if none).
std::map<std::string, std::string> exported_row(const std::string& csv_text,
                                                const std::string& trial) {
  std::istringstream csv(csv_text);
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> header;
  for (std::istringstream h(line); std::getline(h, line, ',');) header.push_back(line);
  std::map<std::string, std::string> row;
  while (std::getline(csv, line)) {
    std::vector<std::string> cells;
    for (std::istringstream c(line); std::getline(c, line, ',');) cells.push_back(line);
    if (cells[0] != trial) continue;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
  }
  return row;
}

TEST(CliReproduceTest, AReplayedSweepTrialEqualsItsStoredRow) {
  const fs::path dir = fresh_dir("reproduce_replay");
  const std::string db = (dir / "sweep.db").string();
  ASSERT_EQ(run_pamsim("sweep scenarios/sweep_smoke.toml --db " + db + " --out " + dir.string())
                .exit_code,
            0);
  const CliResult exported = run_pamsim("export " + db + " --csv -");
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  // the stored row of trial 13 (point 6, seed 2), by column name
  std::map<std::string, std::string> stored = exported_row(exported.out, "13");
  ASSERT_EQ(stored["trial"], "13");
  // the database records what made it
  {
    const pamsim::ResultsDb opened = pamsim::ResultsDb::open_existing(db);
    EXPECT_EQ(opened.meta("mujoco_version"), "2.2.2");
    EXPECT_FALSE(opened.meta("git_commit").empty());
    const nlohmann::json runs = nlohmann::json::parse(opened.meta("invocations"));
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_EQ(runs[0]["trials_run"], 32);
    EXPECT_EQ(runs[0]["command_line"][1], "sweep");
  }

  const fs::path out = dir / "trial_13";
  const CliResult replay =
      run_pamsim("replay " + db + " --trial 13 --no-plot --out " + out.string());
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  EXPECT_NE(replay.err.find("the replay equals the stored trial"), std::string::npos) << replay.err;
  const nlohmann::json summary = json_of(out / "summary.json");
  EXPECT_EQ(summary["seed"].get<double>(), std::stod(stored["seed"]));
  int compared = 0;
  for (const auto& [name, value] : summary.items()) {
    if (!stored.count(name) || !value.is_number() || stored[name].empty()) continue;
    EXPECT_EQ(value.get<double>(), std::stod(stored[name])) << name;
    ++compared;
  }
  EXPECT_GE(compared, 10);
  // its full time series, and a folder that reruns
  EXPECT_GT(line_count(read_file(out / "trajectory.csv")), 100);
  const CliResult rerun =
      run_pamsim("run --from " + out.string() + " --no-plot --out " + (dir / "rerun").string());
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_EQ(read_file(dir / "rerun" / "trajectory.csv"), read_file(out / "trajectory.csv"));

  // bad input: one line, exit 2
  for (const std::string& args :
       {"replay " + db + " --trial 999", "replay " + db + " --trial -1",
        "replay " + (dir / "none.db").string() + " --trial 0", "replay " + db}) {
    const CliResult bad = run_pamsim(args);
    EXPECT_EQ(bad.exit_code, 2) << args;
    EXPECT_EQ(line_count(bad.err), 1) << args << ": " << bad.err;
  }
  EXPECT_EQ(run_pamsim("replay " + db + " --trial 13 --no-plot --out " + out.string()).exit_code, 2)
      << "an earlier replay's outputs, without --force";
}

}  // namespace
