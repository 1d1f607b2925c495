// plot.cc: see plot.h. Each plot is a gnuplot script plus whitespace-separated .dat files
// in a private temp folder; gnuplot runs there and writes a temp PNG next to the target.
#include "sim/io/plot.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <utility>

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

// unique temp names across threads of this process
std::atomic<unsigned long> g_plot_counter{0};

// a gnuplot single-quoted string literal ('' escapes a quote)
std::string gp_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "''";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out + "'";
}

// a POSIX shell single-quoted word
std::string sh_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "'\\''";
    else out += c;
  }
  return out + "'";
}

// a number for a .dat file or a script; non-finite as "nan" (missing, see set datafile)
std::string num(double v) {
  if (!std::isfinite(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.9g", v);
  return buf;
}

// the gnuplot executable on PATH, or "" if there is none
std::string find_gnuplot() {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return "";
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) dir = ".";
    const std::string candidate = dir + "/gnuplot";
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return candidate;
  }
  return "";
}

// a private folder under the system temp folder, removed with everything in it
class TempDir {
 public:
  explicit TempDir(const std::string& png_path) {
    std::error_code ec;
    const fs::path base = fs::temp_directory_path(ec);
    if (ec) throw std::runtime_error(png_path + ": no temp folder for gnuplot (" + ec.message() + ")");
    for (int attempt = 0; attempt < 100; ++attempt) {
      const fs::path p = base / ("pamsim_plot_" + std::to_string(::getpid()) + "_" +
                                 std::to_string(g_plot_counter++));
      if (fs::create_directory(p, ec)) {
        path_ = p;
        return;
      }
      if (ec) break;
    }
    throw std::runtime_error(png_path + ": cannot create a temp folder in " + base.string() +
                             (ec ? " (" + ec.message() + ")" : ""));
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

// the line of gnuplot's stderr that says what went wrong
std::string first_error_line(const std::string& err) {
  static const std::regex located(R"("[^"]*" line [0-9]+: .*)");
  std::stringstream lines(err);
  std::string line, first;
  while (std::getline(lines, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto b = line.find_first_not_of(" \t");
    if (b == std::string::npos) continue;
    line = line.substr(b);
    if (std::regex_match(line, located)) return line;
    if (first.empty()) first = line;
  }
  return first;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A plot to draw: data files by name (in the temp folder) and the script body.
struct GnuplotJob {
  int width_px = kAnglePlotWidthPx;
  int height_px = kAnglePlotHeightPx;
  std::vector<std::pair<std::string, std::string>> data_files;   // name, content
  std::string script;
};

// Runs `job` and moves its PNG to png_path; throws std::runtime_error naming png_path.
void run_gnuplot(const std::string& png_path, const GnuplotJob& job) {
  // gnuplot must exist and the target folder too (gnuplot's own message would name a temp file)
  const std::string gnuplot = find_gnuplot();
  if (gnuplot.empty()) {
    throw std::runtime_error(png_path +
                             ": gnuplot not found on PATH (install gnuplot-nox, pngcairo terminal)");
  }
  const fs::path target = fs::absolute(png_path);
  if (!fs::is_directory(target.parent_path())) {
    throw std::runtime_error(png_path + ": cannot write the plot, no folder " +
                             target.parent_path().string());
  }

  // data and script into the temp folder; output to a temp PNG beside the target
  const TempDir dir(png_path);
  const std::string tmp_png = target.string() + ".tmp." + std::to_string(::getpid()) + "." +
                              std::to_string(g_plot_counter++) + ".png";
  auto write = [&](const std::string& name, const std::string& content) {
    std::ofstream out(dir.path() / name, std::ios::binary);
    out << content;
    out.close();
    if (!out) {
      throw std::runtime_error(png_path + ": cannot write gnuplot input " +
                               (dir.path() / name).string());
    }
  };
  for (const auto& [name, content] : job.data_files) write(name, content);
  std::ostringstream script;
  script << "set terminal pngcairo size " << job.width_px << "," << job.height_px
         << " noenhanced font 'sans,11'\n"
         << "set output " << gp_quote(tmp_png) << "\n"
         << "set datafile missing 'nan'\n"
         << job.script << "unset output\n";
  write("plot.gp", script.str());

  // run it in the temp folder, stderr captured
  const std::string command = "cd " + sh_quote(dir.path().string()) + " && " + sh_quote(gnuplot) +
                              " plot.gp >gnuplot.out 2>gnuplot.err";
  const int rc = std::system(command.c_str());
  std::error_code ec;
  const bool exited_ok = rc != -1 && WIFEXITED(rc) && WEXITSTATUS(rc) == 0;
  const bool wrote_png = fs::is_regular_file(tmp_png, ec) && fs::file_size(tmp_png, ec) > 0;
  if (!exited_ok || !wrote_png) {
    fs::remove(tmp_png, ec);
    std::string why = first_error_line(read_text(dir.path() / "gnuplot.err"));
    if (why.empty()) {
      why = rc == -1             ? std::string("cannot start a shell")
            : !WIFEXITED(rc)     ? "killed by signal " + std::to_string(WTERMSIG(rc))
            : WEXITSTATUS(rc) != 0 ? "exit status " + std::to_string(WEXITSTATUS(rc))
                                   : std::string("no image written");
    }
    throw std::runtime_error(png_path + ": gnuplot failed: " + why);
  }

  // into place
  if (std::rename(tmp_png.c_str(), target.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    fs::remove(tmp_png, ec);
    throw std::runtime_error(png_path + ": cannot move the plot into place: " + why);
  }
}

// [lo, hi] of the finite values; false if there are none
bool finite_range(const std::vector<double>& v, double& lo, double& hi) {
  lo = INFINITY;
  hi = -INFINITY;
  for (double x : v) {
    if (!std::isfinite(x)) continue;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  return lo <= hi;
}

// "set xrange [a:b]", widened if the trajectory has a single time
std::string xrange_line(const std::vector<double>& time_s) {
  double lo, hi;
  if (!finite_range(time_s, lo, hi)) lo = 0, hi = 1;
  if (hi <= lo) hi = lo + 1;
  return "set xrange [" + num(lo) + ":" + num(hi) + "]\n";
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
      dat += num(b.time_s[r]) + " " + num(b.mean[r]) + " " + num(b.min[r]) + " " +
             num(b.max[r]) + "\n";
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
    s << "set arrow from " << num(drop_time_s) << ", graph 0 to " << num(drop_time_s)
      << ", graph 1 nohead dt 2 lw 1.5 lc rgb 'black'\n";
    extra_keys = ", keyentry with lines dt 2 lw 1.5 lc rgb 'black' title 'drop (release)'";
  }

  // bands first (semi-transparent), then the mean lines on top
  s << "plot ";
  const std::size_t n_colours = sizeof(kBandColours) / sizeof(kBandColours[0]);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::string colour = kBandColours[k % n_colours];
    const std::string label =
        runs[k].label + " range (" + std::to_string(runs[k].trials) + " trials)";
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
    dat += num(t[r]) + " " + num(q[r]);
    for (const auto& p : pressure) dat += " " + num(p[r]);
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
    s << "set arrow 1 from " << num(impact) << ", graph 0 to " << num(impact)
      << ", graph 1 nohead dt 2 lw 1.5 lc rgb 'black'\n";
    keys += ", keyentry with lines dt 2 lw 1.5 lc rgb 'black' title 'impact'";
  }
  for (std::size_t j = 0; j < labels.size(); ++j) {
    const char* shade = kMuscleShade[j % kPalette];
    for (const auto& [w0, w1] : reflex[j]) {
      s << "set object " << object++ << " rect from " << num(w0) << ", graph 0 to " << num(w1)
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
    s << ", " << num(start) << " with lines dt 3 lw 1.5 lc rgb '#555555' title "
      << gp_quote("start angle " + num(std::round(start * 10) / 10) + " deg");
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
                            std::to_string(trials.size()) + " trials (mean and range)";
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

void write_heatmap(const std::string& png_path, const HeatMap& map) {
  const std::size_t nx = map.x_levels.size(), ny = map.y_levels.size();
  if (!map.scattered && map.cells.size() != nx * ny) {
    throw std::invalid_argument(png_path + ": heat map has " + std::to_string(map.cells.size()) +
                                " cells for " + std::to_string(nx) + " x " + std::to_string(ny) +
                                " levels");
  }
  if (map.scattered && (map.x.size() != map.values.size() || map.y.size() != map.values.size())) {
    throw std::invalid_argument(png_path + ": heat map points and values differ in number");
  }
  GnuplotJob job;
  job.width_px = kHeatMapWidthPx;
  job.height_px = kHeatMapHeightPx;
  std::ostringstream s;
  s << "set title " << gp_quote(map.title) << " font ',14'\n"
    << "set xlabel " << gp_quote(map.x_label) << "\nset ylabel " << gp_quote(map.y_label) << "\n"
    << "set cblabel " << gp_quote(map.value_label) << "\n"
    // viridis: dark is low, yellow is high; no data is grey
    << "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', "
       "1 '#fde725')\n"
    << "set object 1 rectangle from graph 0,0 to graph 1,1 behind fc rgb '#d0d0d0' fs solid noborder\n"
    << "set key outside bottom center horizontal\n";
  double lo = map.value_min, hi = map.value_max;
  double data_lo, data_hi;
  const std::vector<double>& all = map.scattered ? map.values : map.cells;
  if (finite_range(all, data_lo, data_hi)) {
    if (!std::isfinite(lo)) lo = data_lo;
    if (!std::isfinite(hi)) hi = data_hi;
  }
  if (std::isfinite(lo) && std::isfinite(hi)) {
    if (hi <= lo) hi = lo + (lo == 0 ? 1.0 : std::fabs(lo) * 0.01);
    s << "set cbrange [" << num(lo) << ":" << num(hi) << "]\n";
  }

  std::string dat;
  std::string mark_plot;
  if (!map.scattered) {
    // cells as boxes in index space, levels as tick labels
    for (std::size_t iy = 0; iy < ny; ++iy) {
      for (std::size_t ix = 0; ix < nx; ++ix) {
        const double v = map.cells[iy * nx + ix];
        if (std::isfinite(v)) dat += num(ix) + " " + num(iy) + " " + num(v) + "\n";
      }
    }
    auto tics = [](const char* axis, const std::vector<std::string>& levels) {
      std::string t = std::string("set ") + axis + "tics (";
      for (std::size_t i = 0; i < levels.size(); ++i) {
        t += (i ? ", " : "") + gp_quote(levels[i]) + " " + std::to_string(i);
      }
      return t + ")\n";
    };
    s << tics("x", map.x_levels) << tics("y", map.y_levels)
      << (nx > 8 ? "set xtics rotate by 45 right\n" : "")
      << "set xrange [-0.5:" << num(nx - 0.5) << "]\nset yrange [-0.5:" << num(ny - 0.5) << "]\n"
      << "set tics scale 0\n";
    s << "plot 'cells.dat' using 1:2:(0.5):(0.5):3 with boxxyerror fc palette fs solid 1.0 "
         "border lc rgb 'white' notitle";
    if (!map.cell_format.empty()) {
      // white text on the dark half of the palette, black on the light half
      const int font = nx * ny > 200 ? 7 : 9;
      const std::string mid = num(std::isfinite(lo) && std::isfinite(hi) ? (lo + hi) / 2 : 0.0);
      for (const auto& [test, colour] : {std::pair{"<", "white"}, {">=", "black"}}) {
        s << ", 'cells.dat' using 1:2:($3 " << test << " " << mid << " ? sprintf("
          << gp_quote(map.cell_format) << ", $3) : '') with labels font '," << font
          << "' tc rgb '" << colour << "' notitle";
      }
    }
    mark_plot = "'mark.dat' using 1:2:(0.5):(0.5) with boxxyerror fs empty border lc rgb '#e31a1c' "
                "lw 3";
  } else {
    for (std::size_t i = 0; i < map.values.size(); ++i) {
      dat += num(map.x[i]) + " " + num(map.y[i]) + " " + num(map.values[i]) + "\n";
    }
    s << (map.x_log ? "set logscale x\n" : "") << (map.y_log ? "set logscale y\n" : "")
      << "set grid\nplot 'cells.dat' using 1:2:3 with points pt 7 ps 1.6 lc palette notitle";
    mark_plot = "'mark.dat' using 1:2 with points pt 6 ps 3 lw 3 lc rgb '#e31a1c'";
  }
  if (map.has_mark) {
    job.data_files.emplace_back("mark.dat", num(map.mark_x) + " " + num(map.mark_y) + "\n");
    s << ", " << mark_plot << " title " << gp_quote(map.mark_label);
  }
  s << "\n";
  if (dat.empty()) dat = "nan nan nan\n";   // nothing to colour: gnuplot still draws the axes
  job.data_files.emplace_back("cells.dat", dat);
  job.script = s.str();
  run_gnuplot(png_path, job);
}

}  // namespace pamsim
