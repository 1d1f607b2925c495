// plot.cc: see plot.h. The figures of a run: the single trial's joint and pressures, the
// band over repeated trials, two runs compared (the heat maps are in heatmap_plot.cc).
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
#include "sim/io/gnuplot.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// colours: agonist red, antagonist blue (lines and their reflex windows); bands cycle
// per muscle, in model order (the arm's agonist red, antagonist blue), then repeating
constexpr const char* kMuscleColour[] = {"#c0392b", "#2166ac", "#1b7837", "#762a83", "#e08214"};
constexpr const char* kMuscleShade[] = {"#f4a582", "#92c5de", "#a6dba0", "#c2a5cf", "#fdb863"};
constexpr std::size_t kPalette = 5;
constexpr const char* kBandColours[] = {"#2166ac", "#c0392b", "#1b9e77", "#7570b3",
                                        "#d95f02", "#e7298a"};

// "set xrange [a:b]", widened if the trajectory has a single time
std::string xrange_line(const std::vector<double>& time_s) {
  double lo, hi;
  if (!finite_range(time_s, lo, hi)) lo = 0, hi = 1;
  if (hi <= lo) hi = lo + 1;
  return "set xrange [" + gp_num(lo) + ":" + gp_num(hi) + "]\n";
}

std::vector<double> column_values(const Trajectory& tr, const std::string& name) {
  const std::size_t c = tr.column(name);
  std::vector<double> v(tr.rows());
  for (std::size_t r = 0; r < v.size(); ++r) v[r] = tr.at(r, c);
  return v;
}

// [start, end) time intervals where flag == 1; a window ends at the next row's time
std::vector<std::pair<double, double>> windows(const std::vector<double>& time_s,
                                               const std::vector<double>& flag) {
  std::vector<std::pair<double, double>> out;
  const std::size_t n = time_s.size();
  const double dt = n > 1 ? time_s[n - 1] - time_s[n - 2] : 0.0;
  std::size_t r = 0;
  while (r < n) {
    if (flag[r] != 1.0) {
      ++r;
      continue;
    }
    const std::size_t begin = r;
    while (r < n && flag[r] == 1.0) ++r;
    out.emplace_back(time_s[begin], r < n ? time_s[r] : time_s[n - 1] + dt);
  }
  return out;
}

std::string file_name(const std::string& path) {
  const std::string name = fs::path(path).filename().string();
  return name.empty() ? path : name;
}

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
    std::string dat = "# time_s mean_deg min_deg max_deg\n";
    for (std::size_t r = 0; r < b.time_s.size(); ++r) {
      dat += gp_num(b.time_s[r]) + " " + gp_num(b.mean[r]) + " " + gp_num(b.min[r]) + " " +
             gp_num(b.max[r]) + "\n";
    }
    job.data_files.emplace_back("band_" + std::to_string(k) + ".dat", dat);
    all_time.insert(all_time.end(), b.time_s.begin(), b.time_s.end());
    all_angle.insert(all_angle.end(), b.min.begin(), b.min.end());
    all_angle.insert(all_angle.end(), b.max.begin(), b.max.end());
  }

  // axes; a fixed y range if no angle is finite (gnuplot refuses an all-missing plot)
  s << "set title " << gp_quote(title) << " font ',14'\n"
    << "set xlabel 'time (s)'\nset ylabel 'angle (deg)'\nset grid\n"
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

  // bands first (semi-transparent), then the mean lines on top
  s << "plot ";
  const std::size_t n_colours = sizeof(kBandColours) / sizeof(kBandColours[0]);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::string colour = kBandColours[k % n_colours];
    const std::string label =
        runs[k].label + " min-max over " + std::to_string(runs[k].trials) + " trials";
    s << (k ? ", " : "") << "'band_" << k << ".dat' using 1:3:4 with filledcurves fc rgb '"
      << colour << "' fs transparent solid 0.25 noborder title " << gp_quote(label);
  }
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::string colour = kBandColours[k % n_colours];
    s << ", 'band_" << k << ".dat' using 1:2 with lines lw 2 lc rgb '" << colour << "' title "
      << gp_quote(runs[k].label + " mean");
  }
  s << extra_keys << "\n";
  job.script = s.str();
  return job;
}

}  // namespace

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
  std::vector<std::size_t> angle_col;
  for (const Trajectory* t : trials) angle_col.push_back(t->column(joint_column(*t)));

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
    throw InputError("--plot-format must be png, svg, pdf or a comma-separated list of them, got '" +
                     text + "'");
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
    const std::string stem = png.substr(0, png.size() - 4);   // "angle.png", "heatmap_*.png"
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

namespace {

// the muscles' labels, from their p_cmd_<m>_MPa columns
std::vector<std::string> muscle_labels(const Trajectory& tr) {
  std::vector<std::string> labels;
  const std::string prefix = "p_cmd_", suffix = "_MPa";
  for (const std::string& c : tr.columns) {
    if (c.size() > prefix.size() + suffix.size() && c.rfind(prefix, 0) == 0 &&
        c.compare(c.size() - suffix.size(), suffix.size(), suffix) == 0) {
      labels.push_back(c.substr(prefix.size(), c.size() - prefix.size() - suffix.size()));
    }
  }
  return labels;
}

}  // namespace

void write_angle_plot(const std::string& png_path, const TrialResult& trial,
                      const Scenario& scenario) {
  const Trajectory& tr = trial.trajectory;
  const TrialSummary& sum = trial.summary;
  if (tr.rows() == 0) throw std::runtime_error(png_path + ": no trajectory rows to plot");

  // the columns drawn: the joint, each muscle's command and chamber pressure and reflex
  const std::string joint = joint_column(tr);
  const bool hinge = joint == "angle_deg";
  const std::vector<double> t = column_values(tr, "time_s");
  const std::vector<double> q = column_values(tr, joint);
  const std::vector<std::string> labels = muscle_labels(tr);
  std::vector<std::vector<double>> pressure;
  std::vector<std::vector<std::pair<double, double>>> reflex;
  for (const std::string& m : labels) {
    pressure.push_back(column_values(tr, "p_cmd_" + m + "_MPa"));
    pressure.push_back(column_values(tr, "p_" + m + "_MPa"));
    reflex.push_back(tr.has_column("reflex_" + m) ? windows(t, column_values(tr, "reflex_" + m))
                                                  : std::vector<std::pair<double, double>>{});
  }

  // data: time, the joint, then command and chamber pressure per muscle
  GnuplotJob job;
  job.width_px = kAnglePlotWidthPx;
  job.height_px = kAnglePlotHeightPx;
  std::string dat = "# time_s " + joint;
  for (const std::string& m : labels) dat += " p_cmd_" + m + "_MPa p_" + m + "_MPa";
  dat += "\n";
  for (std::size_t r = 0; r < t.size(); ++r) {
    dat += gp_num(t[r]) + " " + gp_num(q[r]);
    for (const auto& p : pressure) dat += " " + gp_num(p[r]);
    dat += "\n";
  }
  job.data_files.emplace_back("angle.dat", dat);

  // title: scenario file, seed, status (and why, when not ok)
  std::string title = file_name(scenario.path) + ", seed " + std::to_string(sum.seed) + ", " +
                      sum.status;
  if (sum.status != "ok" && !sum.message.empty()) {
    title += ": " + (sum.message.size() > 80 ? sum.message.substr(0, 77) + "..." : sum.message);
  }
  std::ostringstream s;
  s << "set multiplot title " << gp_quote(title) << " font ',14'\n"
    << "set lmargin at screen 0.08\nset rmargin at screen 0.97\n"
    << xrange_line(t) << "set grid\nset key top right box opaque width 2\n";

  // top panel: the joint, the impact, the reflex windows, the start angle
  double lo, hi;
  s << "set tmargin at screen 0.92\nset bmargin at screen 0.42\n"
    << "set format x ''\nunset xlabel\nset ylabel '" << (hinge ? "angle (deg)" : "position (mm)")
    << "'\n";
  if (!finite_range(q, lo, hi)) s << "set yrange [-1:1]\n";
  int object = 1;
  std::string keys;
  const double impact = sum.metric("impact_time_s");
  if (std::isfinite(impact)) {
    s << "set arrow 1 from " << gp_num(impact) << ", graph 0 to " << gp_num(impact)
      << ", graph 1 nohead dt 2 lw 1.5 lc rgb 'black'\n";
    keys += ", keyentry with lines dt 2 lw 1.5 lc rgb 'black' title 'impact'";
  }
  for (std::size_t j = 0; j < labels.size(); ++j) {
    const char* shade = kMuscleShade[j % kPalette];
    for (const auto& [w0, w1] : reflex[j]) {
      s << "set object " << object++ << " rect from " << gp_num(w0) << ", graph 0 to " << gp_num(w1)
        << ", graph 1 behind fc rgb '" << shade << "' fs transparent solid 0.45 noborder\n";
    }
    if (!reflex[j].empty()) {
      keys += std::string(", keyentry with boxes fs solid 0.6 noborder fc rgb '") + shade +
              "' title " + gp_quote("reflex " + labels[j]);
    }
  }
  s << "plot 'angle.dat' using 1:2 with lines lw 2 lc rgb 'black' title "
    << gp_quote(hinge ? "angle" : "position");
  const double start = sum.metric("start_angle_deg");
  if (hinge && std::isfinite(start)) {
    s << ", " << gp_num(start) << " with lines dt 3 lw 1.5 lc rgb '#555555' title "
      << gp_quote("start angle " + gp_num(std::round(start * 10) / 10) + " deg");
  }
  s << keys << "\n";

  // bottom panel: commanded (dashed) and chamber (solid) pressures
  s << "unset object\nunset arrow\n"
    << "set tmargin at screen 0.40\nset bmargin at screen 0.08\n"
    << "set format x '% h'\nset xlabel 'time (s)'\nset ylabel 'pressure (MPa)'\n";
  std::vector<double> all_p;
  for (const auto& p : pressure) all_p.insert(all_p.end(), p.begin(), p.end());
  if (!finite_range(all_p, lo, hi)) s << "set yrange [0:1]\n";
  if (labels.empty()) s << "set label 1 'no muscles' at graph 0.5, 0.5 center\nplot NaN notitle\n";
  for (std::size_t j = 0; j < labels.size(); ++j) {
    const char* colour = kMuscleColour[j % kPalette];
    s << (j == 0 ? "plot " : ", ") << "'angle.dat' using 1:" << 3 + 2 * j
      << " with lines dt 2 lw 1.5 lc rgb '" << colour << "' title " << gp_quote(labels[j] + " command")
      << ", '' using 1:" << 4 + 2 * j << " with lines lw 2 lc rgb '" << colour << "' title "
      << gp_quote(labels[j] + " chamber");
  }
  s << "\nunset multiplot\n";
  job.script = s.str();
  run_gnuplot(png_path, job);
}

void write_angle_band_plot(const std::string& png_path,
                           const std::vector<const Trajectory*>& trials,
                           const Scenario& scenario) {
  if (trials.empty()) throw std::runtime_error(png_path + ": no trajectories to plot");
  const std::string name = fs::path(scenario.path).stem().string();
  const BandSeries band = angle_band(trials, name.empty() ? "angle" : name);
  if (band.time_s.empty()) throw std::runtime_error(png_path + ": no trajectory rows to plot");
  const std::string title = file_name(scenario.path) + ": angle over " +
                            std::to_string(trials.size()) + " trials (mean, band: min-max)";
  const EventSpec* release = scenario.event("release");
  const double drop_time_s =
      release && release->when.kind == ConditionKind::kTime ? release->when.at_s : kNaN;
  run_gnuplot(png_path, band_job({band}, title, std::isfinite(drop_time_s) ? drop_time_s : kNaN));
}

void write_compare_plot(const std::string& png_path, const std::vector<BandSeries>& runs) {
  if (runs.empty()) throw std::runtime_error(png_path + ": no runs to compare");
  std::string title = "angle: ";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const BandSeries& b = runs[k];
    if (b.mean.size() != b.time_s.size() || b.min.size() != b.time_s.size() ||
        b.max.size() != b.time_s.size()) {
      throw std::invalid_argument(png_path + ": band '" + b.label + "' has columns of different lengths");
    }
    if (b.time_s.empty()) throw std::runtime_error(png_path + ": band '" + b.label + "' is empty");
    title += (k ? " vs " : "") + b.label;
  }
  run_gnuplot(png_path, band_job(runs, title + " (mean and range)", kNaN));
}

}  // namespace pamsim
