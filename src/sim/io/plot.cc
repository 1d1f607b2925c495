// plot.cc: see plot.h. The figures over several trials: the band over repeated trials, two
// runs compared; the plot formats (the single trial's figure is in trial_plot.cc, the heat
// maps in heatmap_plot.cc).
#include "sim/io/plot.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "base/input_error.h"
#include "base/no_value.h"
#include "sim/io/figure_text.h"
#include "sim/io/gnuplot.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// the band plots' runs, in order, then repeating
constexpr const char* kBandColours[] = {"#2166ac", "#c0392b", "#1b9e77",
                                        "#7570b3", "#d95f02", "#e7298a"};

// the band plot body shared by angle_band.png and compare.png
GnuplotJob band_job(const std::vector<BandSeries>& runs, const std::string& title,
                    double drop_time_s) {
  GnuplotJob job;
  job.width_px = kBandPlotWidthPx;
  job.height_px = kBandPlotHeightPx;
  std::ostringstream s;

  // one data file per run: time, mean, min, max
  std::vector<double> all_time, all_angle;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const BandSeries& b = runs[k];
    std::string dat = "# time_s mean_" + b.unit + " min_" + b.unit + " max_" + b.unit + "\n";
    for (std::size_t r = 0; r < b.time_s.size(); ++r) {
      dat += gp_num(b.time_s[r]) + " " + gp_num(b.mean[r]) + " " + gp_num(b.min[r]) + " " +
             gp_num(b.max[r]) + "\n";
    }
    job.data_files.emplace_back("band_" + std::to_string(k) + ".dat", dat);
    all_time.insert(all_time.end(), b.time_s.begin(), b.time_s.end());
    all_angle.insert(all_angle.end(), b.min.begin(), b.min.end());
    all_angle.insert(all_angle.end(), b.max.begin(), b.max.end());
  }

  // axes (the joint of the first run: compare checks they agree); a fixed y range if no value
  // is finite (gnuplot refuses an all-missing plot)
  s << "set title " << gp_quote(title) << " font ',14'\n"
    << "set xlabel 'time (s)'\nset ylabel '" << runs.front().quantity << " (" << runs.front().unit
    << ")'\nset grid\n"
    << "set key top right box opaque width 2\n"
    << xrange_line(all_time);
  double lo, hi;
  if (!finite_range(all_angle, lo, hi)) s << "set yrange [-1:1]\n";

  // the release of the mass, dashed
  std::string extra_keys;
  if (std::isfinite(drop_time_s)) {
    s << "set arrow from " << gp_num(drop_time_s) << ", graph 0 to " << gp_num(drop_time_s)
      << ", graph 1 nohead dt 2 lw 1.5 lc rgb 'black'\n";
    extra_keys = ", keyentry with lines dt 2 lw 1.5 lc rgb 'black' title 'drop (release)'";
  }

  const std::vector<std::string> items = band_plot_items(runs);
  s << "plot ";
  for (std::size_t i = 0; i < items.size(); ++i) s << (i ? ", " : "") << items[i];
  s << extra_keys << "\n";
  job.script = s.str();
  return job;
}

}  // namespace

// bands first (semi-transparent), then the lines on top
std::vector<std::string> band_plot_items(const std::vector<BandSeries>& runs) {
  std::vector<std::string> items;
  const std::size_t n_colours = sizeof(kBandColours) / sizeof(kBandColours[0]);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (runs[k].trials < 2) continue;
    const std::string label =
        runs[k].label + " min-max over " + std::to_string(runs[k].trials) + " trials";
    items.push_back("'band_" + std::to_string(k) + ".dat' using 1:3:4 with filledcurves fc rgb '" +
                    kBandColours[k % n_colours] + "' fs transparent solid 0.25 noborder title " +
                    gp_quote(label));
  }
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::string label = runs[k].trials < 2 ? runs[k].label : runs[k].label + " mean";
    items.push_back("'band_" + std::to_string(k) + ".dat' using 1:2 with lines lw 2 lc rgb '" +
                    kBandColours[k % n_colours] + "' title " + gp_quote(label));
  }
  return items;
}

BandSeries angle_band(const std::vector<const Trajectory*>& trials, std::string label) {
  if (trials.empty()) throw std::invalid_argument("angle_band: no trajectories");
  for (const Trajectory* t : trials) {
    if (t == nullptr) throw std::invalid_argument("angle_band: null trajectory");
  }

  // the common rows: the shortest trajectory's
  std::size_t rows = trials.front()->rows();
  for (const Trajectory* t : trials) rows = std::min(rows, t->rows());
  BandSeries b;
  b.label = std::move(label);
  b.trials = trials.size();
  b.time_s.resize(rows);
  b.mean.assign(rows, kNaN);
  b.min.assign(rows, kNaN);
  b.max.assign(rows, kNaN);
  const std::size_t time_col = trials.front()->column("time_s");
  const std::string joint = joint_column(*trials.front());
  if (joint == "position_mm") {
    b.quantity = "position";
    b.unit = "mm";
  }
  std::vector<std::size_t> angle_col;
  for (const Trajectory* t : trials) {
    if (joint_column(*t) != joint) {
      throw std::invalid_argument("angle_band: trials of a hinge and of a slide joint mixed");
    }
    angle_col.push_back(t->column(joint));
  }

  // per row, over the trials where the angle is finite
  for (std::size_t r = 0; r < rows; ++r) {
    b.time_s[r] = trials.front()->at(r, time_col);
    double sum = 0, lo = INFINITY, hi = -INFINITY;
    int n = 0;
    for (std::size_t k = 0; k < trials.size(); ++k) {
      const double a = trials[k]->at(r, angle_col[k]);
      if (!std::isfinite(a)) continue;
      sum += a;
      lo = std::min(lo, a);
      hi = std::max(hi, a);
      ++n;
    }
    if (n > 0) {
      b.mean[r] = sum / n;
      b.min[r] = lo;
      b.max[r] = hi;
    }
  }
  return b;
}

std::string joint_column(const Trajectory& tr) {
  for (const char* name : {"angle_deg", "position_mm"}) {
    if (tr.has_column(name)) return name;
  }
  throw std::out_of_range("no trajectory column angle_deg or position_mm");
}

void use_plot_formats(const std::string& text) {
  std::vector<std::string> extra;
  std::stringstream in(text);
  std::string item;
  bool ok = !text.empty();
  while (std::getline(in, item, ',')) {
    if (item == "svg" || item == "pdf") {
      if (std::find(extra.begin(), extra.end(), item) == extra.end()) extra.push_back(item);
    } else if (item != "png") {
      ok = false;
    }
  }
  if (!ok) {
    throw InputError(
        "--plot-format must be png, svg, pdf or a comma-separated list of them, got '" + text +
        "'");
  }
  set_extra_plot_formats(extra);
}

std::vector<std::string> plot_formats(const std::string& text) {
  std::vector<std::string> formats = {"png"};
  for (const char* f : {"svg", "pdf"}) {
    if (text.find(f) != std::string::npos) formats.push_back(f);
  }
  return formats;
}

std::vector<std::string> plot_file_names(const std::vector<std::string>& png_names) {
  std::vector<std::string> names;
  for (const std::string& png : png_names) {
    const std::string stem = png.substr(0, png.size() - 4);  // "angle.png", "heatmap_*.png"
    for (const char* ext : {".png", ".svg", ".pdf"}) names.push_back(stem + ext);
  }
  return names;
}

bool plots_wanted(bool no_plot) {
  if (no_plot) return false;
  if (!find_gnuplot().empty()) return true;
  std::cerr << "pamsim: gnuplot not found on PATH: plots skipped (install gnuplot-nox for "
               "them, or pass --no-plot)\n";
  return false;
}

std::string trial_plot_name(const Trajectory& tr) {
  return tr.has_column("position_mm") && !tr.has_column("angle_deg") ? "position.png" : "angle.png";
}

void write_angle_band_plot(const std::string& png_path,
                           const std::vector<const Trajectory*>& trials, const Scenario& scenario) {
  if (trials.empty()) throw std::runtime_error(png_path + ": no trajectories to plot");
  const std::string name = fs::path(scenario.path).stem().string();
  const BandSeries band = angle_band(trials, name.empty() ? "angle" : name);
  if (band.time_s.empty()) throw std::runtime_error(png_path + ": no trajectory rows to plot");
  const std::string title = file_name(scenario.path) + ": " + band.quantity + " over " +
                            std::to_string(trials.size()) + " trials (mean, band: min-max)";
  const EventSpec* release = scenario.event("release");
  const double drop_time_s =
      release && release->when.kind == ConditionKind::kTime ? release->when.at_s : kNaN;
  run_gnuplot(png_path, band_job({band}, title, std::isfinite(drop_time_s) ? drop_time_s : kNaN));
}

void write_compare_plot(const std::string& png_path, const std::vector<BandSeries>& runs) {
  if (runs.empty()) throw std::runtime_error(png_path + ": no runs to compare");
  std::string title = runs.front().quantity + ": ";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const BandSeries& b = runs[k];
    if (b.quantity != runs.front().quantity) {
      throw std::invalid_argument(png_path + ": band '" + b.label + "' is a " + b.quantity +
                                  ", the first a " + runs.front().quantity);
    }
    if (b.mean.size() != b.time_s.size() || b.min.size() != b.time_s.size() ||
        b.max.size() != b.time_s.size()) {
      throw std::invalid_argument(png_path + ": band '" + b.label +
                                  "' has columns of different lengths");
    }
    if (b.time_s.empty()) throw std::runtime_error(png_path + ": band '" + b.label + "' is empty");
    title += (k ? " vs " : "") + b.label;
  }
  const bool bands =
      std::any_of(runs.begin(), runs.end(), [](const BandSeries& b) { return b.trials > 1; });
  run_gnuplot(png_path, band_job(runs, bands ? title + " (mean and range)" : title, kNaN));
}

}  // namespace pamsim
