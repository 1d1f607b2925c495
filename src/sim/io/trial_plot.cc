// trial_plot.cc: write_angle_plot of plot.h, angle.png (or position.png): the single trial's
// joint with the impact, the reflex windows and the start angle over each muscle's commanded
// and chamber pressure.
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "sim/io/figure_text.h"
#include "sim/io/gnuplot.h"
#include "sim/io/plot.h"

namespace pamsim {
namespace {

// colours: agonist red, antagonist blue (lines and their reflex windows); bands cycle
// per muscle, in model order (the arm's agonist red, antagonist blue), then repeating
constexpr const char* kMuscleColour[] = {"#c0392b", "#2166ac", "#1b7837", "#762a83", "#e08214"};
constexpr const char* kMuscleShade[] = {"#f4a582", "#92c5de", "#a6dba0", "#c2a5cf", "#fdb863"};
constexpr std::size_t kPalette = 5;

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

// What the single-trial figure draws: the joint, each muscle's command and chamber
// pressure (in pairs, in the order of `labels`) and its reflex windows.
struct AnglePlotColumns {
  std::string joint;  // angle_deg or position_mm
  bool hinge = false;
  std::vector<double> t, q;
  std::vector<std::string> labels;
  std::vector<std::vector<double>> pressure;
  std::vector<std::vector<std::pair<double, double>>> reflex;
};

AnglePlotColumns angle_plot_columns(const Trajectory& tr) {
  AnglePlotColumns c;
  c.joint = joint_column(tr);
  c.hinge = c.joint == "angle_deg";
  c.t = column_values(tr, "time_s");
  c.q = column_values(tr, c.joint);
  c.labels = muscle_labels(tr);
  for (const std::string& m : c.labels) {
    c.pressure.push_back(column_values(tr, "p_cmd_" + m + "_MPa"));
    c.pressure.push_back(column_values(tr, "p_" + m + "_MPa"));
    c.reflex.push_back(tr.has_column("reflex_" + m) ? windows(c.t, column_values(tr, "reflex_" + m))
                                                    : std::vector<std::pair<double, double>>{});
  }
  return c;
}

// angle.dat: time, the joint, then command and chamber pressure per muscle
std::string angle_plot_data(const AnglePlotColumns& c) {
  std::string dat = "# time_s " + c.joint;
  for (const std::string& m : c.labels) dat += " p_cmd_" + m + "_MPa p_" + m + "_MPa";
  dat += "\n";
  for (std::size_t r = 0; r < c.t.size(); ++r) {
    dat += gp_num(c.t[r]) + " " + gp_num(c.q[r]);
    for (const auto& p : c.pressure) dat += " " + gp_num(p[r]);
    dat += "\n";
  }
  return dat;
}

// title: scenario file, seed, status (and why, when not ok)
std::string angle_plot_title(const Scenario& scenario, const TrialSummary& sum) {
  std::string title =
      file_name(scenario.path) + ", seed " + std::to_string(sum.seed) + ", " + sum.status;
  if (sum.status != "ok" && !sum.message.empty()) {
    title += ": " + (sum.message.size() > 80 ? sum.message.substr(0, 77) + "..." : sum.message);
  }
  return title;
}

// top panel: the joint, the impact, the reflex windows, the start angle
void joint_panel(std::ostringstream& s, const AnglePlotColumns& c, const TrialSummary& sum) {
  double lo, hi;
  s << "set tmargin at screen 0.92\nset bmargin at screen 0.42\n"
    << "set format x ''\nunset xlabel\nset ylabel '" << (c.hinge ? "angle (deg)" : "position (mm)")
    << "'\n";
  if (!finite_range(c.q, lo, hi)) s << "set yrange [-1:1]\n";
  int object = 1;
  std::string keys;
  const double impact = sum.metric("impact_time_s");
  if (std::isfinite(impact)) {
    s << "set arrow 1 from " << gp_num(impact) << ", graph 0 to " << gp_num(impact)
      << ", graph 1 nohead dt 2 lw 1.5 lc rgb 'black'\n";
    keys += ", keyentry with lines dt 2 lw 1.5 lc rgb 'black' title 'impact'";
  }
  for (std::size_t j = 0; j < c.labels.size(); ++j) {
    const char* shade = kMuscleShade[j % kPalette];
    for (const auto& [w0, w1] : c.reflex[j]) {
      s << "set object " << object++ << " rect from " << gp_num(w0) << ", graph 0 to " << gp_num(w1)
        << ", graph 1 behind fc rgb '" << shade << "' fs transparent solid 0.45 noborder\n";
    }
    if (!c.reflex[j].empty()) {
      keys += std::string(", keyentry with boxes fs solid 0.6 noborder fc rgb '") + shade +
              "' title " + gp_quote("reflex " + c.labels[j]);
    }
  }
  s << "plot 'angle.dat' using 1:2 with lines lw 2 lc rgb 'black' title "
    << gp_quote(c.hinge ? "angle" : "position");
  const double start = sum.metric("start_angle_deg");
  if (c.hinge && std::isfinite(start)) {
    s << ", " << gp_num(start) << " with lines dt 3 lw 1.5 lc rgb '#555555' title "
      << gp_quote("start angle " + gp_num(std::round(start * 10) / 10) + " deg");
  }
  s << keys << "\n";
}

// bottom panel: commanded (dashed) and chamber (solid) pressures
void pressure_panel(std::ostringstream& s, const AnglePlotColumns& c) {
  double lo, hi;
  s << "unset object\nunset arrow\n"
    << "set tmargin at screen 0.40\nset bmargin at screen 0.08\n"
    << "set format x '% h'\nset xlabel 'time (s)'\nset ylabel 'pressure (MPa)'\n";
  std::vector<double> all_p;
  for (const auto& p : c.pressure) all_p.insert(all_p.end(), p.begin(), p.end());
  if (!finite_range(all_p, lo, hi)) s << "set yrange [0:1]\n";
  if (c.labels.empty())
    s << "set label 1 'no muscles' at graph 0.5, 0.5 center\nplot NaN notitle\n";
  for (std::size_t j = 0; j < c.labels.size(); ++j) {
    const char* colour = kMuscleColour[j % kPalette];
    s << (j == 0 ? "plot " : ", ") << "'angle.dat' using 1:" << 3 + 2 * j
      << " with lines dt 2 lw 1.5 lc rgb '" << colour << "' title "
      << gp_quote(c.labels[j] + " command") << ", '' using 1:" << 4 + 2 * j
      << " with lines lw 2 lc rgb '" << colour << "' title " << gp_quote(c.labels[j] + " chamber");
  }
  s << "\nunset multiplot\n";
}

}  // namespace

void write_angle_plot(const std::string& png_path, const TrialResult& trial,
                      const Scenario& scenario) {
  const Trajectory& tr = trial.trajectory;
  const TrialSummary& sum = trial.summary;
  if (tr.rows() == 0) throw std::runtime_error(png_path + ": no trajectory rows to plot");

  // the columns drawn: the joint, each muscle's command and chamber pressure and reflex
  const AnglePlotColumns c = angle_plot_columns(tr);
  GnuplotJob job;
  job.width_px = kAnglePlotWidthPx;
  job.height_px = kAnglePlotHeightPx;
  job.data_files.emplace_back("angle.dat", angle_plot_data(c));

  std::ostringstream s;
  s << "set multiplot title " << gp_quote(angle_plot_title(scenario, sum)) << " font ',14'\n"
    << "set lmargin at screen 0.08\nset rmargin at screen 0.97\n"
    << xrange_line(c.t) << "set grid\nset key top right box opaque width 2\n";
  joint_panel(s, c, sum);
  pressure_panel(s, c);
  job.script = s.str();
  run_gnuplot(png_path, job);
}

}  // namespace pamsim
