// plot_test.cc: the gnuplot figures (angle, band, compare) on synthetic trajectories, the
// trajectory.csv reader behind `pamsim compare`, and the compare command itself (in process).
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

namespace pamsim {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// a falling-mass trial shape: rest at -36 deg, impact at 1 s, damped swing, reflex windows
Trajectory synthetic_trajectory(double offset_deg, std::size_t rows = 301) {
  Trajectory tr;
  tr.columns = make_log_layout(true, {"ball"}, {"ago", "anta"}, true).columns;
  tr.values.assign(rows * tr.columns.size(), 0.0);
  auto set = [&](std::size_t r, const char* name, double v) {
    tr.values[r * tr.columns.size() + tr.column(name)] = v;
  };
  for (std::size_t r = 0; r < rows; ++r) {
    const double t = 0.01 * static_cast<double>(r);
    const double after = t >= 1.0 ? t - 1.0 : 0.0;
    const bool ago = t >= 1.05 && t < 1.25;
    const bool anta = t >= 1.30 && t < 1.40;
    set(r, "time_s", t);
    set(r, "angle_deg", -36.0 + offset_deg - 12.0 * std::exp(-4.0 * after) * std::sin(8.0 * after));
    set(r, "p_cmd_ago_MPa", ago ? 0.7 : 0.4);
    set(r, "p_ago_MPa", 0.4 + (t >= 1.05 ? 0.25 * std::exp(-3.0 * (t - 1.05)) : 0.0));
    set(r, "p_cmd_anta_MPa", anta ? 0.2 : 0.4);
    set(r, "p_anta_MPa", anta ? 0.3 : 0.4);
    set(r, "reflex_ago", ago ? 1.0 : 0.0);
    set(r, "reflex_anta", anta ? 1.0 : 0.0);
    set(r, "fiber_rate_ago_mm_s", kNaN);
  }
  set(50, "angle_deg", kNaN);   // a missing sample must not break the plot
  return tr;
}

TrialResult synthetic_trial() {
  TrialResult r;
  r.summary.seed = 7;
  r.summary.metrics = {{"start_angle_deg", -36.0}, {"impact_time_s", 1.0}};
  r.trajectory = synthetic_trajectory(0.0);
  return r;
}

Scenario synthetic_scenario() {
  Scenario sc;
  sc.path = "scenarios/synthetic_drop.toml";
  return sc;
}

struct PngSize {
  bool ok = false;
  unsigned width = 0, height = 0;
};

// the PNG signature and the IHDR chunk's width and height
PngSize read_png_size(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char b[24] = {};
  in.read(reinterpret_cast<char*>(b), sizeof(b));
  PngSize s;
  const unsigned char sig[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
  if (!in || !std::equal(sig, sig + 8, b) || std::string(b + 12, b + 16) != "IHDR") return s;
  auto be32 = [&](int i) {
    return (unsigned(b[i]) << 24) | (unsigned(b[i + 1]) << 16) | (unsigned(b[i + 2]) << 8) |
           unsigned(b[i + 3]);
  };
  s.ok = true;
  s.width = be32(16);
  s.height = be32(20);
  return s;
}

std::set<std::string> entries(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.insert(e.path().filename().string());
  return out;
}

// this process's plot temp folders still in the system temp folder
int leftover_plot_temp_dirs() {
  const std::string prefix = "pamsim_plot_" + std::to_string(::getpid()) + "_";
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::temp_directory_path())) {
    if (e.path().filename().string().rfind(prefix, 0) == 0) ++n;
  }
  return n;
}

class PlotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("pamsim_plot_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(PlotTest, AnglePlotIsAPngOfTheConfiguredSize) {
  write_angle_plot(path("angle.png"), synthetic_trial(), synthetic_scenario());
  const PngSize s = read_png_size(path("angle.png"));
  ASSERT_TRUE(s.ok);
  EXPECT_EQ(s.width, unsigned(kAnglePlotWidthPx));
  EXPECT_EQ(s.height, unsigned(kAnglePlotHeightPx));
  EXPECT_EQ(entries(dir_), std::set<std::string>{"angle.png"});
  EXPECT_EQ(leftover_plot_temp_dirs(), 0);
}

TEST_F(PlotTest, AnglePlotWithoutImpactOrReflexOrAngle) {
  // a passive, diverged trial: no impact, no reflex window, every angle missing
  TrialResult r = synthetic_trial();
  r.summary.status = "diverged";
  r.summary.message = "CVODE failed at t = 1.2 s";
  r.summary.metrics = {{"start_angle_deg", kNaN}, {"impact_time_s", kNaN}};
  for (std::size_t row = 0; row < r.trajectory.rows(); ++row) {
    for (const char* name : {"reflex_ago", "reflex_anta", "angle_deg"}) {
      r.trajectory.values[row * r.trajectory.columns.size() + r.trajectory.column(name)] =
          std::string(name) == "angle_deg" ? kNaN : 0.0;
    }
  }
  write_angle_plot(path("angle.png"), r, synthetic_scenario());
  EXPECT_TRUE(read_png_size(path("angle.png")).ok);
}

TEST_F(PlotTest, AngleBandIsMeanMinMaxOverTheShortestTrial) {
  const Trajectory a = synthetic_trajectory(0.0, 200);
  const Trajectory b = synthetic_trajectory(2.0, 150);
  const Trajectory c = synthetic_trajectory(4.0, 180);
  const BandSeries band = angle_band({&a, &b, &c}, "model");
  EXPECT_EQ(band.label, "model");
  EXPECT_EQ(band.trials, 3u);
  ASSERT_EQ(band.time_s.size(), 150u);
  const std::size_t angle = a.column("angle_deg");
  EXPECT_DOUBLE_EQ(band.time_s[120], 1.2);
  EXPECT_DOUBLE_EQ(band.mean[120], a.at(120, angle) + 2.0);
  EXPECT_DOUBLE_EQ(band.min[120], a.at(120, angle));
  EXPECT_DOUBLE_EQ(band.max[120], a.at(120, angle) + 4.0);
  // row 50 is missing in every trial
  EXPECT_TRUE(std::isnan(band.mean[50]));
  EXPECT_THROW(angle_band({}, "none"), std::invalid_argument);
}

TEST_F(PlotTest, AngleBandIgnoresMissingValuesOfSomeTrials) {
  Trajectory a = synthetic_trajectory(0.0, 100);
  const Trajectory b = synthetic_trajectory(2.0, 100);
  a.values[10 * a.columns.size() + a.column("angle_deg")] = kNaN;
  const BandSeries band = angle_band({&a, &b}, "x");
  EXPECT_DOUBLE_EQ(band.mean[10], b.at(10, b.column("angle_deg")));
  EXPECT_DOUBLE_EQ(band.min[10], band.max[10]);
}

// A slide joint's log (the pulley rig): position_mm where a hinge logs angle_deg.
Trajectory slide_trajectory(double offset_mm, std::size_t rows = 100) {
  Trajectory tr;
  tr.columns = make_log_layout(false, {}, {"pam"}, false).columns;
  tr.values.assign(rows * tr.columns.size(), 0.0);
  for (std::size_t r = 0; r < rows; ++r) {
    tr.values[r * tr.columns.size() + tr.column("time_s")] = 0.01 * static_cast<double>(r);
    tr.values[r * tr.columns.size() + tr.column("position_mm")] = offset_mm + 0.1 * r;
  }
  return tr;
}

TEST_F(PlotTest, ABandOfASlideIsItsPositionInMillimetresAndJointsDoNotMix) {
  const Trajectory a = slide_trajectory(0.0), b = slide_trajectory(4.0);
  const BandSeries band = angle_band({&a, &b}, "pulley");
  EXPECT_EQ(band.quantity, "position");
  EXPECT_EQ(band.unit, "mm");
  EXPECT_DOUBLE_EQ(band.mean[30], 0.1 * 30 + 2.0);   // the mean of 3 and 7 mm
  EXPECT_EQ(angle_band({&a}, "x").trials, 1u);
  const Trajectory hinge = synthetic_trajectory(0.0);
  EXPECT_EQ(angle_band({&hinge}, "arm").quantity, "angle");
  EXPECT_THROW(angle_band({&a, &hinge}, "mixed"), std::invalid_argument);
  // a compare plot of a slide and a hinge is refused, one of slides drawn
  EXPECT_THROW(write_compare_plot(path("mixed.png"), {band, angle_band({&hinge}, "arm")}),
               std::invalid_argument);
  write_compare_plot(path("slides.png"), {band, angle_band({&b}, "one")});
  EXPECT_TRUE(read_png_size(path("slides.png")).ok);
}

TEST_F(PlotTest, BandPlotIsAPngOfTheConfiguredSize) {
  std::vector<Trajectory> trials;
  for (int k = 0; k < 20; ++k) trials.push_back(synthetic_trajectory(0.3 * k));
  std::vector<const Trajectory*> ptrs;
  for (const auto& t : trials) ptrs.push_back(&t);
  write_angle_band_plot(path("angle_band.png"), ptrs, synthetic_scenario());
  const PngSize s = read_png_size(path("angle_band.png"));
  ASSERT_TRUE(s.ok);
  EXPECT_EQ(s.width, unsigned(kBandPlotWidthPx));
  EXPECT_EQ(s.height, unsigned(kBandPlotHeightPx));
  EXPECT_EQ(entries(dir_), std::set<std::string>{"angle_band.png"});
  EXPECT_EQ(leftover_plot_temp_dirs(), 0);
}

TEST_F(PlotTest, ComparePlotIsAPngOfTheConfiguredSize) {
  const Trajectory a0 = synthetic_trajectory(0.0), a1 = synthetic_trajectory(1.5);
  const Trajectory b0 = synthetic_trajectory(3.0), b1 = synthetic_trajectory(5.0, 250);
  const std::vector<BandSeries> runs = {angle_band({&a0, &a1}, "model"),
                                        angle_band({&b0, &b1}, "fiber sensor's")};
  write_compare_plot(path("compare.png"), runs);
  const PngSize s = read_png_size(path("compare.png"));
  ASSERT_TRUE(s.ok);
  EXPECT_EQ(s.width, unsigned(kBandPlotWidthPx));
  EXPECT_EQ(s.height, unsigned(kBandPlotHeightPx));
  EXPECT_EQ(entries(dir_), std::set<std::string>{"compare.png"});
  EXPECT_THROW(write_compare_plot(path("none.png"), {}), std::runtime_error);
}

TEST_F(PlotTest, PlotsFromManyThreadsDoNotCollide) {
  const Trajectory a = synthetic_trajectory(0.0), b = synthetic_trajectory(2.0);
  const Scenario sc = synthetic_scenario();
  std::vector<std::thread> threads;
  std::vector<int> ok(4, 0);
  for (int k = 0; k < 4; ++k) {
    threads.emplace_back([&, k] {
      write_angle_band_plot(path("band_" + std::to_string(k) + ".png"), {&a, &b}, sc);
      ok[k] = 1;
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(ok, std::vector<int>(4, 1));
  EXPECT_EQ(entries(dir_).size(), 4u);
  for (int k = 0; k < 4; ++k) EXPECT_TRUE(read_png_size(path("band_" + std::to_string(k) + ".png")).ok);
  EXPECT_EQ(leftover_plot_temp_dirs(), 0);
}

TEST_F(PlotTest, MissingFolderThrowsAndLeavesNothing) {
  const std::string png = path("no_such_folder/angle.png");
  try {
    write_angle_plot(png, synthetic_trial(), synthetic_scenario());
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(png + ": ", 0), 0u) << e.what();
  }
  EXPECT_TRUE(entries(dir_).empty());
  EXPECT_EQ(leftover_plot_temp_dirs(), 0);
}

TEST_F(PlotTest, UnwritableFolderThrowsAndLeavesNothing) {
  // a folder gnuplot cannot write to: read-only by mode, or /proc when running as root
  fs::path folder = dir_ / "read_only";
  fs::create_directories(folder);
  fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
  if (::geteuid() == 0) folder = "/proc";
  const std::string png = (folder / "pamsim_plot_test.png").string();
  try {
    write_angle_plot(png, synthetic_trial(), synthetic_scenario());
    FAIL() << "expected an exception";
  } catch (const std::runtime_error& e) {
    // the temp PNG cannot be made beside it: said before gnuplot runs
    EXPECT_EQ(std::string(e.what()).rfind(png + ": cannot write (", 0), 0u) << e.what();
  }
  for (const auto& name : entries(folder)) EXPECT_EQ(name.find("pamsim_plot_test"), std::string::npos);
  EXPECT_EQ(leftover_plot_temp_dirs(), 0);
  fs::permissions(dir_ / "read_only", fs::perms::owner_all);
}

// A disk that fills while gnuplot writes the PNG, emulated by a file-size limit that gnuplot
// inherits (SIGXFSZ ignored, so its writes fail with EFBIG): gnuplot exits 0 with half an
// image, which used to be renamed into place as the plot (issue 14 item 1).
TEST_F(PlotTest, APngCutShortByAFullDiskIsAnErrorAndLeavesNothing) {
  const std::string png = path("angle.png");
  struct rlimit old {};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  struct rlimit small = old;
  small.rlim_cur = 16 * 1024;   // the data files fit, the 1200x900 image does not
  const auto old_handler = ::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  try {
    write_angle_plot(png, synthetic_trial(), synthetic_scenario());
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  ::signal(SIGXFSZ, old_handler);
  EXPECT_EQ(message.rfind(png + ": gnuplot failed: ", 0), 0u) << message;
  EXPECT_TRUE(entries(dir_).empty()) << "no half PNG, no temp file";
  EXPECT_EQ(leftover_plot_temp_dirs(), 0);
}

TEST_F(PlotTest, MissingGnuplotSaysSo) {
  const std::string old_path = std::getenv("PATH") ? std::getenv("PATH") : "";
  ::setenv("PATH", dir_.c_str(), 1);
  const Trajectory tr = synthetic_trajectory(0.0);
  std::string message;
  try {
    write_compare_plot(path("compare.png"), {angle_band({&tr}, "a")});
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  ::setenv("PATH", old_path.c_str(), 1);
  EXPECT_NE(message.find("gnuplot not found"), std::string::npos) << message;
  EXPECT_TRUE(entries(dir_).empty());
}

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
  const std::string out = run_compare({(dir_ / "model").string(), (dir_ / "fiber").string(), "-o",
                                       path("cmp.png"), "--label-a", "model", "--label-b", "fiber"});
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
