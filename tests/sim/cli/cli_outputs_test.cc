// cli_outputs_test.cc: what every command does with its outputs: an earlier output is
// replaced only with --force (one line and exit 2 without it, the file untouched), a report
// with --no-plot draws no heat maps, plots come as SVG or PDF beside the PNG, and "-" is
// standard input and output.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "sim/cli_util.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::fresh_dir;
using pamsim_test::kShortDrop;
using pamsim_test::line_count;
using pamsim_test::read_file;
using pamsim_test::run_pamsim;

nlohmann::json json_file(const fs::path& path) { return nlohmann::json::parse(read_file(path)); }

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
                .exit_code,
            0);
  ASSERT_EQ(run_pamsim("tensile --params " + models + "table4_agonist.toml -o " +
                       (dir / "t.csv").string())
                .exit_code,
            0);
  // folders that hold an earlier run's file
  existing("frames/frame_00000.png");
  existing("val/table5.csv");
  existing("rep/points.csv");
  struct Case {
    std::string args;
    fs::path output;
  };
  const std::vector<Case> cases = {
      {"tensile --params " + models + "table4_agonist.toml -o " + existing("a.csv"), dir / "a.csv"},
      {"fit --model eq3 " + (dir / "t.csv").string() + " -o " + existing("f.toml"), dir / "f.toml"},
      {"export " + db + " -o " + existing("e.csv"), dir / "e.csv"},
      {"export " + db + " --csv " + existing("e2.csv"), dir / "e2.csv"},
      {"render scenarios/drop_mass.toml -o " + existing("v.mp4"), dir / "v.mp4"},
      {"render scenarios/drop_mass.toml --png-dir " + (dir / "frames").string() + " -o " +
           (dir / "new.mp4").string(),
       dir / "frames/frame_00000.png"},
      {"run scenarios/drop_mass.toml --out " + (dir / "r").string() + " --video " +
           existing("r.mp4"),
       dir / "r.mp4"},
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
}

TEST(CliReproduceTest, AReportWithNoPlotDrawsNoHeatMaps) {
  const fs::path dir = fresh_dir("reproduce_no_plot_report");
  const std::string db = (dir / "sweep.db").string();
  ASSERT_EQ(run_pamsim("sweep scenarios/sweep_smoke.toml --db " + db + " --out " + dir.string())
                .exit_code,
            0);
  const CliResult report =
      run_pamsim("report " + db + " --no-plot --out " + (dir / "rep2").string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  EXPECT_TRUE(fs::exists(dir / "rep2" / "points.csv"));
  EXPECT_EQ(json_file(dir / "rep2" / "provenance.json")["from"], db);
  for (const auto& e : fs::directory_iterator(dir / "rep2")) {
    EXPECT_NE(e.path().extension(), ".png") << e.path();
  }
}

TEST(CliReproduceTest, PlotsComeAsSvgOrPdfBesideThePng) {
  const fs::path dir = fresh_dir("reproduce_plot_format");
  const std::string run = "run scenarios/drop_mass.toml --out " + (dir / "a").string() + kShortDrop;
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

// "-" is standard output for a file argument and standard input for an input file: a
// tensile test piped into a fit gives the fit of the file; a scenario read from stdin runs
// as the file does (its paths relative to the current folder).
TEST(CliReproduceTest, DashIsStandardInputAndOutput) {
  const fs::path dir = fresh_dir("reproduce_dash");
  const std::string tensile =
      "tensile --params models/pams/table4_agonist.toml --seed 3 "
      "--noise-force-N 0.2 -o ";
  ASSERT_EQ(run_pamsim(tensile + (dir / "t.csv").string()).exit_code, 0);
  const CliResult piped =
      run_pamsim(tensile + "- | " + std::string(PAMSIM_BINARY) + " fit --model eq3 - -o -");
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  const CliResult from_file = run_pamsim("fit --model eq3 " + (dir / "t.csv").string() + " -o " +
                                         (dir / "f.toml").string());
  ASSERT_EQ(from_file.exit_code, 0) << from_file.err;
  // the same parameters (the source line names the input)
  const std::string file = read_file(dir / "f.toml");
  const auto coefficients = [](const std::string& toml) {
    return toml.substr(toml.find("[spring]"));
  };
  EXPECT_EQ(coefficients(piped.out), coefficients(file));
  EXPECT_NE(piped.err.find("fitted to -"), std::string::npos) << "the table goes to stderr";
  // two things on stdout are refused
  const CliResult both = run_pamsim("fit --model eq3 " + (dir / "t.csv").string() + " -o - --json");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_EQ(line_count(both.err), 1) << both.err;

  const CliResult stdin_run =
      run_pamsim("run - --no-plot --out " + (dir / "s").string() + kShortDrop + " < drop_mass.toml",
                 "cd scenarios &&");
  ASSERT_EQ(stdin_run.exit_code, 0) << stdin_run.err;
  const CliResult file_run = run_pamsim("run scenarios/drop_mass.toml --no-plot --out " +
                                        (dir / "f").string() + kShortDrop);
  ASSERT_EQ(file_run.exit_code, 0) << file_run.err;
  EXPECT_EQ(read_file(dir / "s" / "trajectory.csv"), read_file(dir / "f" / "trajectory.csv"));
}

}  // namespace
