// cli_reproduce_test.cc: outputs that can be traced and reproduced, and a command line that
// can be scripted (issue 15): a run's folder records what made it and `run --from` rebuilds
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

#include "cli_util.h"
#include "sim/sweep/results_db.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::read_file;
using pamsim_test::run_pamsim;

const std::string kShort = " --set sim.duration_s=1.5 drop.time_s=0.3";

nlohmann::json json_of(const fs::path& path) { return nlohmann::json::parse(read_file(path)); }

TEST(CliReproduceTest, ARunFromItsFolderWritesByteIdenticalOutputs) {
  const fs::path dir = fresh_dir("reproduce_from");
  for (const int trials : {1, 2}) {
    const fs::path a = dir / ("a" + std::to_string(trials));
    const fs::path b = dir / ("b" + std::to_string(trials));
    const CliResult first = run_pamsim("run scenarios/drop_mass.toml --no-plot --trials " +
                                       std::to_string(trials) + " --out " + a.string() + kShort +
                                       " reflex.v_thr_mm_s=55");
    ASSERT_EQ(first.exit_code, 0) << first.err;
    const CliResult again = run_pamsim("run --from " + a.string() + " --no-plot --out " + b.string());
    ASSERT_EQ(again.exit_code, 0) << again.err;
    EXPECT_EQ(again.out, first.out);   // the summary printed
    const std::vector<std::string> files =
        trials == 1 ? std::vector<std::string>{"trajectory.csv", "summary.json"}
                    : std::vector<std::string>{"summary.json", "trial_0000/trajectory.csv",
                                               "trial_0000/summary.json", "trial_0001/trajectory.csv",
                                               "trial_0001/summary.json"};
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

  // the inputs are fingerprinted: a file changed since the run is named when it runs again
  const std::string calibration =
      std::string(PAMSIM_SOURCE_DIR) + "/models/arm_2pam_plant_calibration.toml";
  fs::copy_file(calibration, dir / "cal.toml");
  const std::string own = pamsim_test::scenario_variant(dir, "drop_mass.toml", calibration,
                                                        (dir / "cal.toml").string());
  ASSERT_EQ(run_pamsim("run " + own + " --no-plot --out " + (dir / "own").string() + kShort)
                .exit_code, 0);
  const nlohmann::json inputs = json_of(dir / "own" / "provenance.json")["inputs"];
  std::set<std::string> keys;
  for (const auto& f : inputs) keys.insert(f["key"].get<std::string>());
  EXPECT_TRUE(keys.count("model.file") && keys.count("model.calibration")) << inputs.dump();
  EXPECT_EQ(run_pamsim("run --from " + (dir / "own").string() + " --no-plot").err.find("changed"),
            std::string::npos);
  pamsim_test::write_text(dir / "cal.toml", read_file(dir / "cal.toml") + "# edited\n");
  const CliResult changed = run_pamsim("run --from " + (dir / "own").string() +
                                       " --no-plot --force");
  EXPECT_EQ(changed.exit_code, 0) << changed.err;
  EXPECT_NE(changed.err.find("model.calibration (" + (dir / "cal.toml").string() + ") changed"),
            std::string::npos) << changed.err;

  // an input path that is no file (a hand-edited provenance.json) is named, not read
  nlohmann::json edited = json_of(dir / "own" / "provenance.json");
  edited["inputs"][0]["path"] = "/dev/zero";
  pamsim_test::write_text(dir / "own" / "provenance.json", edited.dump(2));
  const CliResult device = run_pamsim("run --from " + (dir / "own").string() + " --no-plot --force");
  EXPECT_EQ(device.exit_code, 0) << device.err;
  EXPECT_NE(device.err.find("(/dev/zero) is gone or not a readable file"), std::string::npos)
      << device.err;

  // bad input
  EXPECT_EQ(run_pamsim("run --from " + (dir / "nothing").string()).exit_code, 2);
  const CliResult both = run_pamsim("run scenarios/drop_mass.toml --from " + (dir / "a1").string());
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
  const CliResult r = run_pamsim("run scenarios/drop_mass.toml --no-plot --trials 3 --threads 2 --out " +
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
  const std::string run = "run scenarios/drop_mass.toml --no-plot --out " + (dir / "out").string() + kShort;
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
  const CliResult quiet = run_pamsim("run scenarios/drop_mass.toml --no-plot --out " +
                                     (dir / "a").string() + kShort);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_FALSE(fs::exists(dir / "a" / "angle.png"));
  EXPECT_EQ(quiet.err.find("gnuplot"), std::string::npos) << quiet.err;
  // no gnuplot on PATH: the run succeeds and says the plots were skipped
  const CliResult without = run_pamsim("run scenarios/drop_mass.toml --out " + (dir / "b").string() +
                                       kShort, "env PATH=" + dir.string());
  ASSERT_EQ(without.exit_code, 0) << without.err;
  EXPECT_TRUE(fs::exists(dir / "b" / "trajectory.csv"));
  EXPECT_FALSE(fs::exists(dir / "b" / "angle.png"));
  EXPECT_NE(without.err.find("gnuplot not found on PATH: plots skipped"), std::string::npos)
      << without.err;
}

TEST(CliReproduceTest, AReplayedSweepTrialEqualsItsStoredRow) {
  const fs::path dir = fresh_dir("reproduce_replay");
  const std::string db = (dir / "sweep.db").string();
  ASSERT_EQ(run_pamsim("sweep scenarios/sweep_smoke.toml --db " + db + " --out " + dir.string())
                .exit_code, 0);
  const CliResult exported = run_pamsim("export " + db + " --csv -");
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  // the stored row of trial 13 (point 6, seed 2), by column name
  std::istringstream csv(exported.out);
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> header;
  for (std::istringstream h(line); std::getline(h, line, ',');) header.push_back(line);
  std::map<std::string, std::string> stored;
  while (std::getline(csv, line)) {
    std::vector<std::string> cells;
    for (std::istringstream c(line); std::getline(c, line, ',');) cells.push_back(line);
    if (cells[0] != "13") continue;
    for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i) stored[header[i]] = cells[i];
  }
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
  const CliResult replay = run_pamsim("replay " + db + " --trial 13 --no-plot --out " + out.string());
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
  const CliResult rerun = run_pamsim("run --from " + out.string() + " --no-plot --out " +
                                     (dir / "rerun").string());
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_EQ(read_file(dir / "rerun" / "trajectory.csv"), read_file(out / "trajectory.csv"));

  // bad input: one line, exit 2
  for (const std::string& args : {"replay " + db + " --trial 999", "replay " + db + " --trial -1",
                                  "replay " + (dir / "none.db").string() + " --trial 0",
                                  "replay " + db}) {
    const CliResult bad = run_pamsim(args);
    EXPECT_EQ(bad.exit_code, 2) << args;
    EXPECT_EQ(line_count(bad.err), 1) << args << ": " << bad.err;
  }
  EXPECT_EQ(run_pamsim("replay " + db + " --trial 13 --no-plot --out " + out.string()).exit_code, 2)
      << "an earlier replay's outputs, without --force";
}

}  // namespace

namespace {

// Every command that writes a file or a folder of its own refuses to replace an earlier one
// without --force (one line, exit 2, the file untouched), and replaces it with --force.
TEST(CliReproduceTest, EveryCommandReplacesAnOutputOnlyWithForce) {
  const fs::path dir = fresh_dir("reproduce_every_force");
  const auto existing = [&](const std::string& name) {
    const fs::path p = dir / name;
    fs::create_directories(p.parent_path());
    pamsim_test::write_text(p, "an earlier output");
    return p.string();
  };
  const std::string models = std::string(PAMSIM_SOURCE_DIR) + "/models/pams/";
  const std::string db = (dir / "sweep.db").string();
  ASSERT_EQ(run_pamsim("sweep scenarios/sweep_smoke.toml --db " + db + " --out " + dir.string())
                .exit_code, 0);
  ASSERT_EQ(run_pamsim("tensile --params " + models + "table4_agonist.toml -o " +
                       (dir / "t.csv").string()).exit_code, 0);
  // folders that hold an earlier run's file
  existing("frames/frame_00000.png");
  existing("val/table5.csv");
  existing("rep/points.csv");
  struct Case {
    std::string args;
    fs::path output;
  };
  const std::vector<Case> cases = {
      {"tensile --params " + models + "table4_agonist.toml -o " + existing("a.csv"),
       dir / "a.csv"},
      {"fit --model eq3 " + (dir / "t.csv").string() + " -o " + existing("f.toml"), dir / "f.toml"},
      {"export " + db + " -o " + existing("e.csv"), dir / "e.csv"},
      {"export " + db + " --csv " + existing("e2.csv"), dir / "e2.csv"},
      {"render scenarios/drop_mass.toml -o " + existing("v.mp4"), dir / "v.mp4"},
      {"render scenarios/drop_mass.toml --png-dir " + (dir / "frames").string() + " -o " +
           (dir / "new.mp4").string(),
       dir / "frames/frame_00000.png"},
      {"run scenarios/drop_mass.toml --out " + (dir / "r").string() + " --video " +
           existing("r.mp4"), dir / "r.mp4"},
      {"calibrate scenarios/drop_mass_passive.toml -o " + existing("c.toml"), dir / "c.toml"},
      {"validate reaching --out " + (dir / "val").string(), dir / "val/table5.csv"},
      {"report " + db + " --out " + (dir / "rep").string(), dir / "rep/points.csv"},
  };
  for (const Case& c : cases) {
    const CliResult r = run_pamsim(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.err;
    EXPECT_EQ(line_count(r.err), 1) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find("--force"), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(read_file(c.output), "an earlier output") << c.args;
  }
  // with --force (the cheap ones; run, replay, validate and report are covered above and in
  // tune_test): the file is the new output
  for (const Case& c : {cases[0], cases[1], cases[2], cases[7]}) {
    const CliResult r = run_pamsim(c.args + " --force");
    EXPECT_EQ(r.exit_code, 0) << c.args << ": " << r.err;
    EXPECT_NE(read_file(c.output), "an earlier output") << c.args;
  }
  // --no-plot: a report without heat maps
  const CliResult report = run_pamsim("report " + db + " --no-plot --out " + (dir / "rep2").string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  EXPECT_TRUE(fs::exists(dir / "rep2" / "points.csv"));
  EXPECT_EQ(json_of(dir / "rep2" / "provenance.json")["from"], db);
  for (const auto& e : fs::directory_iterator(dir / "rep2")) {
    EXPECT_NE(e.path().extension(), ".png") << e.path();
  }
}

}  // namespace

namespace {

TEST(CliReproduceTest, PlotsComeAsSvgOrPdfBesideThePng) {
  const fs::path dir = fresh_dir("reproduce_plot_format");
  const std::string run = "run scenarios/drop_mass.toml --out " + (dir / "a").string() + kShort;
  const CliResult both = run_pamsim(run + " --plot-format svg,pdf");
  ASSERT_EQ(both.exit_code, 0) << both.err;
  for (const char* f : {"angle.png", "angle.svg", "angle.pdf"}) {
    EXPECT_TRUE(fs::exists(dir / "a" / f)) << f;
  }
  EXPECT_NE(read_file(dir / "a" / "angle.svg").find("</svg>"), std::string::npos);
  EXPECT_EQ(read_file(dir / "a" / "angle.pdf").rfind("%PDF", 0), 0u);
  // a new run replaces the whole set: no SVG of the earlier one is left beside its PNG
  ASSERT_EQ(run_pamsim(run + " --force").exit_code, 0);
  EXPECT_TRUE(fs::exists(dir / "a" / "angle.png"));
  EXPECT_FALSE(fs::exists(dir / "a" / "angle.svg"));
  EXPECT_FALSE(fs::exists(dir / "a" / "angle.pdf"));
  // bad input: one line, exit 2, before anything runs
  for (const char* bad : {"jpg", "", "png,gif"}) {
    const CliResult r = run_pamsim(run + " --force --plot-format '" + bad + "'");
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--plot-format"), std::string::npos) << r.err;
  }
}

}  // namespace

namespace {

// "-" is standard output for a file argument and standard input for an input file: a
// tensile test piped into a fit gives the fit of the file; a scenario read from stdin runs
// as the file does (its paths relative to the current folder).
TEST(CliReproduceTest, DashIsStandardInputAndOutput) {
  const fs::path dir = fresh_dir("reproduce_dash");
  const std::string tensile = "tensile --params models/pams/table4_agonist.toml --seed 3 "
                              "--noise-force-N 0.2 -o ";
  ASSERT_EQ(run_pamsim(tensile + (dir / "t.csv").string()).exit_code, 0);
  const CliResult piped = run_pamsim(tensile + "- | " + std::string(PAMSIM_BINARY) +
                                     " fit --model eq3 - -o -");
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  const CliResult from_file = run_pamsim("fit --model eq3 " + (dir / "t.csv").string() + " -o " +
                                         (dir / "f.toml").string());
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  // the same parameters (the source line names the input)
  const std::string file = read_file(dir / "f.toml");
  const auto coefficients = [](const std::string& toml) { return toml.substr(toml.find("[spring]")); };
  EXPECT_EQ(coefficients(piped.out), coefficients(file));
  EXPECT_NE(piped.err.find("fitted to -"), std::string::npos) << "the table goes to stderr";
  // two things on stdout are refused
  const CliResult both = run_pamsim("fit --model eq3 " + (dir / "t.csv").string() + " -o - --json");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_EQ(line_count(both.err), 1) << both.err;

  const CliResult stdin_run = run_pamsim("run - --no-plot --out " + (dir / "s").string() + kShort +
                                         " < drop_mass.toml", "cd scenarios &&");
  ASSERT_EQ(stdin_run.exit_code, 0) << stdin_run.err;
  const CliResult file_run = run_pamsim("run scenarios/drop_mass.toml --no-plot --out " +
                                        (dir / "f").string() + kShort);
  ASSERT_EQ(file_run.exit_code, 0) << file_run.err;
  EXPECT_EQ(read_file(dir / "s" / "trajectory.csv"), read_file(dir / "f" / "trajectory.csv"));
}

}  // namespace
