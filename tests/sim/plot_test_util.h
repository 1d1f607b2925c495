// plot_test_util.h: what the figure and compare tests share (plot_test.cc,
// compare_test.cc): a synthetic falling-mass trajectory and trial, a PNG's size, and a
// fixture with a fresh folder per test.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "reflex/stretch_reflex_controller.h"
#include "sim/io/outputs.h"
#include "sim/io/plot.h"
#include "sim/io/trajectory_csv.h"

namespace pamsim::plot_test {

namespace fs = std::filesystem;

// a falling-mass trial shape: rest at -36 deg, impact at 1 s, damped swing, reflex windows
inline Trajectory synthetic_trajectory(double offset_deg, std::size_t rows = 301) {
  Trajectory tr;
  tr.columns = make_log_layout(true, {"ball"}, {"ago", "anta"}, reflex_channels(false)).columns;
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
    set(r, "fiber_rate_ago_mm_s", std::numeric_limits<double>::quiet_NaN());
  }
  set(50, "angle_deg", std::numeric_limits<double>::quiet_NaN());  // a missing sample: no break
  return tr;
}

inline TrialResult synthetic_trial() {
  TrialResult r;
  r.summary.seed = 7;
  r.summary.metrics = {{"start_angle_deg", -36.0}, {"impact_time_s", 1.0}};
  r.trajectory = synthetic_trajectory(0.0);
  return r;
}

inline Scenario synthetic_scenario() {
  Scenario sc;
  sc.path = "scenarios/synthetic_drop.toml";
  return sc;
}

struct PngSize {
  bool ok = false;
  unsigned width = 0, height = 0;
};

// the PNG signature and the IHDR chunk's width and height
inline PngSize read_png_size(const fs::path& path) {
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

}  // namespace pamsim::plot_test
