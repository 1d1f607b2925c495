// plot_test.cc: the gnuplot figures (angle, band, compare's) on synthetic trajectories
// (plot_test_util.h): their sizes, bands over trials, many threads, and failures (a missing
// or unwritable folder, a full disk, no gnuplot) that leave nothing behind.
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

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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
  tr.columns = make_log_layout(false, {}, {"pam"}).columns;
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
  EXPECT_DOUBLE_EQ(band.mean[30], 0.1 * 30 + 2.0);  // the mean of 3 and 7 mm
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
  for (int k = 0; k < 4; ++k)
    EXPECT_TRUE(read_png_size(path("band_" + std::to_string(k) + ".png")).ok);
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
  for (const auto& name : entries(folder))
    EXPECT_EQ(name.find("pamsim_plot_test"), std::string::npos);
  EXPECT_EQ(leftover_plot_temp_dirs(), 0);
  fs::permissions(dir_ / "read_only", fs::perms::owner_all);
}

// A disk that fills while gnuplot writes the PNG, emulated by a file-size limit that gnuplot
// inherits (SIGXFSZ ignored, so its writes fail with EFBIG): gnuplot exits 0 with half an
// image, which must not be renamed into place as the plot.
TEST_F(PlotTest, APngCutShortByAFullDiskIsAnErrorAndLeavesNothing) {
  const std::string png = path("angle.png");
  struct rlimit old {};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  struct rlimit small = old;
  small.rlim_cur = 16 * 1024;  // the data files fit, the 1200x900 image does not
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

}  // namespace
}  // namespace pamsim

namespace pamsim {
namespace {

// The legend lists only what is drawn: a run of one trial has no band (it would be invisible)
// and its line is named as the run, not as a mean.
TEST(BandPlotItemsTest, ASingleTrialHasNoBandAndItsLineIsTheRun) {
  BandSeries one, three;
  one.label = "passive";
  one.trials = 1;
  three.label = "reflex";
  three.trials = 3;
  const std::vector<std::string> items = band_plot_items({three, one});
  ASSERT_EQ(items.size(), 3u);  // the reflex's band, then both lines
  EXPECT_NE(items[0].find("filledcurves"), std::string::npos);
  EXPECT_NE(items[0].find("'reflex min-max over 3 trials'"), std::string::npos) << items[0];
  EXPECT_NE(items[1].find("title 'reflex mean'"), std::string::npos) << items[1];
  EXPECT_NE(items[2].find("title 'passive'"), std::string::npos) << items[2];
  for (const std::string& item : items) {
    EXPECT_EQ(item.find("passive min-max"), std::string::npos) << item;
  }
}

}  // namespace
}  // namespace pamsim
