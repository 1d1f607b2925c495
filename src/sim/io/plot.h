// plot.h: the figures of a run, drawn by gnuplot (gnuplot.h: data and script in a private
// temp folder, the PNG made beside its place and renamed into it once whole, so a failed
// plot leaves no partial file; plots may be drawn from many threads).
//   angle.png       the joint vs time with the impact, the reflex windows and every muscle's
//                   pressures (commanded and chamber), like the paper's Fig. 8
//                   (position.png for a slide joint, e.g. the pulley rig);
//   angle_band.png  mean and range of the angle over repeated trials, like Fig. 9;
//   compare_<A>_vs_<B>.png  two runs' bands on one plot (model vs fiber sensor, Fig. 9);
//   heatmap_*.png   a sweep metric over two axes (pamsim report).
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "sim/core/scenario.h"
#include "sim/core/trial.h"

namespace pamsim {

// Image sizes [px].
inline constexpr int kAnglePlotWidthPx = 1200;  // angle.png
inline constexpr int kAnglePlotHeightPx = 900;
inline constexpr int kBandPlotWidthPx = 1200;  // angle_band.png and compare.png
inline constexpr int kBandPlotHeightPx = 800;
inline constexpr int kHeatMapWidthPx = 1100;  // heatmap_*.png
inline constexpr int kHeatMapHeightPx = 900;

// The joint over repeated trials, per time row: mean, min and max of its column (angle_deg
// of a hinge, position_mm of a slide) over the trials where it is finite (NaN where none
// is). time_s is the first trial's; trials of different lengths are cut to the shortest.
struct BandSeries {
  std::string label;                             // legend text
  std::size_t trials = 0;                        // how many trajectories went in
  std::string quantity = "angle", unit = "deg";  // "position", "mm" for a slide joint
  std::vector<double> time_s, mean, min, max;
};

// The joint's column of a trajectory: angle_deg (hinge) or position_mm (slide); throws
// std::out_of_range if it has neither. trial_plot_name: "angle.png" or "position.png".
std::string joint_column(const Trajectory& trajectory);
std::string trial_plot_name(const Trajectory& trajectory);

// The band of the joint's column (angle_deg or position_mm). Throws std::invalid_argument
// if `trials` is empty or holds a null pointer or trials of both joint kinds, and
// std::out_of_range if a trajectory lacks time_s or the joint.
BandSeries angle_band(const std::vector<const Trajectory*>& trials, std::string label);

// A value over two sweep axes. On a grid, one cell per pair of levels (index space, the
// levels as tick labels, so a log axis is evenly spaced); for scattered designs, one
// coloured point per sample at its coordinates.
struct HeatMap {
  std::string title;
  std::string x_label, y_label, value_label;
  bool scattered = false;
  // grid: cells[iy * x_levels.size() + ix], NaN where there is no value (drawn grey)
  std::vector<std::string> x_levels, y_levels;
  std::vector<double> cells;
  // scattered: one value per (x, y)
  std::vector<double> x, y, values;
  bool x_log = false, y_log = false;
  // colour range; NaN: the data's range
  double value_min = std::numeric_limits<double>::quiet_NaN();
  double value_max = std::numeric_limits<double>::quiet_NaN();
  // the value printed in each grid cell (C format, e.g. "%.2g"); empty: none
  std::string cell_format;
  // or each grid cell's own text (e.g. "8.62 ± 0.05", the mean and the spread beside it),
  // one per cell, in place of cell_format where given
  std::vector<std::string> cell_texts;
  // the legend entry of the grey cells without a value ("no trial ran ok"); empty: none
  std::string missing_label;
  // a marked cell (grid: indices) or point (scattered: coordinates), e.g. the best setting
  bool has_mark = false;
  double mark_x = 0, mark_y = 0;
  std::string mark_label;
};

// Whether a command draws its plots: not with --no-plot (`no_plot`), and not without gnuplot
// on PATH, which is said once on stderr ("pamsim: gnuplot not found on PATH: plots skipped
// ..."): the command's other outputs do not need it.
bool plots_wanted(bool no_plot);

// --plot-format: "png" (the default), or "svg", "pdf", "svg,pdf" beside the PNG. Sets them
// for every plot of the process (set_extra_plot_formats). Throws InputError "--plot-format
// must be png, svg, pdf or a comma-separated list of them, got ..." otherwise.
void use_plot_formats(const std::string& text);
// The extensions --plot-format asks for, PNG first: {"png"}, {"png", "svg"}, ...
// (use_plot_formats validates the text).
std::vector<std::string> plot_formats(const std::string& text);
// The file names a plot named `png_name` may have ("angle.png" -> also "angle.svg",
// "angle.pdf"), for the outputs a command owns (StagedOutputs).
std::vector<std::string> plot_file_names(const std::vector<std::string>& png_names);

// Throws std::runtime_error if gnuplot is missing or fails (message names the file).
void write_angle_plot(const std::string& png_path, const TrialResult& trial,
                      const Scenario& scenario);
void write_angle_band_plot(const std::string& png_path,
                           const std::vector<const Trajectory*>& trials, const Scenario& scenario);
// Two (or more) runs' bands on one axis, one colour each, with a legend.
void write_compare_plot(const std::string& png_path, const std::vector<BandSeries>& runs);
// The gnuplot plot items of bands (band_<k>.dat): each band of two or more trials as its
// min-max area, then each run's line (its mean, or a single trial as itself), titled as the
// legend shows them: a run of one trial has no band, so its legend lists only its line.
std::vector<std::string> band_plot_items(const std::vector<BandSeries>& runs);
// Throws std::invalid_argument if the cells or points do not match the levels or each other.
// Without cell_texts, a grid cell prints its value with cell_format.
void write_heatmap(const std::string& png_path, const HeatMap& map);

}  // namespace pamsim
