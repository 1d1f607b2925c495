// compare_test.cc: the trajectory.csv reader behind `pamsim compare` (round trip, CRLF, bad
// input naming the file and line) and the compare command itself, in process, on synthetic
// runs (plot_test_util.h).
#include <CLI/CLI.hpp>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "sim/cli/commands.h"
#include "sim/io/outputs.h"
#include "sim/io/plot.h"
#include "sim/io/trajectory_csv.h"
#include "sim/plot_test_util.h"

namespace pamsim {
namespace {

using namespace plot_test;  // the synthetic trial, read_png_size, PlotTest

// trajectory.csv

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string input_error_of(const std::string& path) {
  try {
    read_trajectory_csv(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST_F(PlotTest, TrajectoryCsvRoundTrip) {
  const Trajectory tr = synthetic_trajectory(1.0, 120);
  write_text(path("trajectory.csv"), trajectory_to_csv(tr));
  const Trajectory back = read_trajectory_csv(path("trajectory.csv"));
  EXPECT_EQ(back.columns, tr.columns);
  ASSERT_EQ(back.values.size(), tr.values.size());
  for (std::size_t i = 0; i < tr.values.size(); ++i) {
    if (std::isnan(tr.values[i])) {
      EXPECT_TRUE(std::isnan(back.values[i])) << i;
    } else {
      EXPECT_NEAR(back.values[i], tr.values[i], 1e-9 * (1 + std::abs(tr.values[i]))) << i;
    }
  }
}

TEST_F(PlotTest, TrajectoryCsvAcceptsCrlfAndBlankLines) {
  write_text(path("t.csv"), "time_s, angle_deg\r\n0, -36\r\n\r\n0.01,nan\r\n");
  const Trajectory tr = read_trajectory_csv(path("t.csv"));
  EXPECT_EQ(tr.columns, (std::vector<std::string>{"time_s", "angle_deg"}));
  ASSERT_EQ(tr.rows(), 2u);
  EXPECT_DOUBLE_EQ(tr.at(0, 1), -36.0);
  EXPECT_TRUE(std::isnan(tr.at(1, 1)));
}

TEST_F(PlotTest, TrajectoryCsvBadInputsNameFileAndLine) {
  const std::string missing = path("missing.csv");
  EXPECT_NE(input_error_of(missing).find(missing + ": "), std::string::npos);

  write_text(path("word.csv"), "time_s,angle_deg\n0,-36\n0.01,abc\n");
  const std::string word = input_error_of(path("word.csv"));
  EXPECT_EQ(word.rfind(path("word.csv") + ": line 3, column angle_deg", 0), 0u) << word;
  EXPECT_NE(word.find("'abc'"), std::string::npos) << word;

  write_text(path("ragged.csv"), "time_s,angle_deg\n0,-36\n0.01,-35\n0.02\n");
  const std::string ragged = input_error_of(path("ragged.csv"));
  EXPECT_EQ(ragged.rfind(path("ragged.csv") + ": line 4 has 1 cells, the header has 2", 0), 0u)
      << ragged;

  write_text(path("empty.csv"), "");
  EXPECT_NE(input_error_of(path("empty.csv")).find("header"), std::string::npos);

  write_text(path("empty_cell.csv"), "time_s,angle_deg\n0,\n");
  EXPECT_NE(input_error_of(path("empty_cell.csv")).find("line 2, column angle_deg"),
            std::string::npos);

  write_text(path("repeat.csv"), "time_s,time_s\n0,0\n");
  EXPECT_NE(input_error_of(path("repeat.csv")).find("repeats column time_s"), std::string::npos);
}

// pamsim compare, in process

// a `pamsim run --trials N` folder (N > 1) or a single-trial folder (N == 1)
void write_run(const fs::path& dir, int trials, double offset_deg) {
  const Scenario sc = synthetic_scenario();
  std::vector<TrialSummary> summaries;
  for (int k = 0; k < trials; ++k) {
    TrialResult r = synthetic_trial();
    r.trajectory = synthetic_trajectory(offset_deg + 0.5 * k);
    r.summary.seed = 1 + k;
    r.summary.metrics.push_back({"peak_drop_deg", 10.0 + k});
    summaries.push_back(r.summary);
    char name[32];
    std::snprintf(name, sizeof(name), "trial_%04d", k);
    write_trial_outputs(trials == 1 ? dir.string() : (dir / name).string(), r, sc);
  }
  if (trials > 1) {
    write_file_atomically((dir / "summary.json").string(),
                          aggregate_summaries(summaries, sc).dump(2) + "\n");
  }
}

// runs `pamsim compare args...` in this process; returns its stdout
std::string run_compare(std::vector<std::string> args) {
  CLI::App app{"pamsim"};
  add_compare_command(app);
  args.insert(args.begin(), {"pamsim", "compare"});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  ::testing::internal::CaptureStdout();
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (...) {
    ::testing::internal::GetCapturedStdout();
    throw;
  }
  return ::testing::internal::GetCapturedStdout();
}

TEST_F(PlotTest, AHeatMapWithAMissingCellAndCellTextsIsDrawn) {
  HeatMap map;
  map.title = "peak drop [deg]: mean ± SD over 2 seeds per point";
  map.x_label = "trigger threshold V_thr [mm/s] (reflex.v_thr_mm_s)";
  map.y_label = "reflex gain k [MPa s/mm], log scale (reflex.k_MPa_s_per_mm)";
  map.value_label = "peak drop [deg], mean over the seeds";
  map.x_levels = {"40", "60"};
  map.y_levels = {"0.001", "0.002"};
  map.cells = {8.5, std::nan(""), 9.0, 9.5};
  map.cell_texts = {"8.5 ± 0.1", "", "9 ± 0.2", "9.5 ± 0"};
  map.missing_label = "no seed ran ok (diverged, failed or not run)";
  write_heatmap(path("h.png"), map);
  EXPECT_TRUE(read_png_size(path("h.png")).ok);
  map.cell_texts.pop_back();
  EXPECT_THROW(write_heatmap(path("bad.png"), map), std::invalid_argument);
  EXPECT_FALSE(fs::exists(path("bad.png")));
}

TEST_F(PlotTest, CompareDrawsBothRunsAndPrintsTheirMetrics) {
  write_run(dir_ / "model", 3, 0.0);
  write_run(dir_ / "fiber", 1, 2.0);
  const std::string out =
      run_compare({(dir_ / "model").string(), (dir_ / "fiber").string(), "-o", path("cmp.png"),
                   "--label-a", "model", "--label-b", "fiber"});
  EXPECT_TRUE(read_png_size(path("cmp.png")).ok);
  EXPECT_NE(out.find("model mean [min, max]"), std::string::npos) << out;
  EXPECT_NE(out.find("fiber mean [min, max]"), std::string::npos) << out;
  // model's peak drop is 10, 11, 12 over its three trials; fiber's single trial is 10
  EXPECT_NE(out.find("peak_drop_deg"), std::string::npos) << out;
  EXPECT_NE(out.find("11 [10, 12]"), std::string::npos) << out;
  EXPECT_NE(out.find("trials"), std::string::npos) << out;
}

TEST_F(PlotTest, CompareWritesUnderRendersByDefaultAndReplacesOnlyWithForce) {
  write_run(dir_ / "model", 2, 0.0);
  write_run(dir_ / "fiber", 2, 2.0);
  // renders/ is relative to where pamsim runs; the folder is restored however the test ends
  struct InFolder {
    fs::path before = fs::current_path();
    explicit InFolder(const fs::path& dir) { fs::current_path(dir); }
    ~InFolder() { fs::current_path(before); }
  } in_folder(dir_);
  run_compare({(dir_ / "model").string() + "/", (dir_ / "fiber").string()});
  const std::string png = path("renders/compare_model_vs_fiber.png");
  EXPECT_TRUE(read_png_size(png).ok);
  EXPECT_THROW(run_compare({(dir_ / "model").string(), (dir_ / "fiber").string()}), InputError);
  EXPECT_NO_THROW(run_compare({(dir_ / "model").string(), (dir_ / "fiber").string(), "--force"}));
  // a plot goes to a file, not a stream
  EXPECT_THROW(run_compare({(dir_ / "model").string(), (dir_ / "fiber").string(), "-o", "-"}),
               InputError);
}

TEST_F(PlotTest, CompareRejectsAFolderThatIsNotARun) {
  write_run(dir_ / "model", 2, 0.0);
  fs::create_directories(dir_ / "empty");
  const std::string empty = (dir_ / "empty").string();
  try {
    run_compare({(dir_ / "model").string(), empty});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(empty + ": not a run folder", 0), 0u) << e.what();
  }
  // a summary.json with metrics but no trial folders
  write_file_atomically((dir_ / "empty" / "summary.json").string(), "{\"metrics\": {}}\n");
  try {
    run_compare({(dir_ / "model").string(), empty});
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(empty + ": not a run folder", 0), 0u) << e.what();
  }
  EXPECT_FALSE(fs::exists(path("compare.png")));
}

}  // namespace
}  // namespace pamsim
