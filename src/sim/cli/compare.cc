// compare.cc: `pamsim compare DIR_A DIR_B [-o FILE.png] [--label-a A --label-b B]`:
// two runs of `pamsim run` (e.g. the reflex with the model vs with the fiber sensor, the
// paper's Fig. 9) as angle bands on one plot, and their metrics side by side on stdout.
// A DIR is either a repeated run (DIR/summary.json with "metrics", DIR/trial_*/trajectory.csv)
// or a single trial (DIR/summary.json without "metrics", DIR/trajectory.csv), a band of one.
// The plot goes to -o, by default renders/compare_<A>_vs_<B>.png; it shows the joint the
// runs log (a hinge's angle_deg, or a slide's position_mm, e.g. the pulley rig).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>

#include <nlohmann/json.hpp>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/io/outputs.h"
#include "sim/io/plot.h"
#include "sim/io/trajectory_csv.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

struct CompareOptions {
  std::string dir_a, dir_b;
  std::string out;
  std::string label_a, label_b;
  bool force = false;
  std::string plot_format = "png";
};

// mean, min, max of one metric over a run's trials; NaN where not defined
struct MetricStats {
  double mean = NAN, min = NAN, max = NAN;
  long count = 0;
};

struct LoadedRun {
  std::string dir;
  std::vector<Trajectory> trajectories;
  std::map<std::string, MetricStats> metrics;  // by name, sorted
};

double number_or_nan(const nlohmann::json& j) { return j.is_number() ? j.get<double>() : NAN; }

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path.string() + ": cannot open");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path.string() + ": not valid JSON (" + e.what() + ")");
  }
}

// the trajectory of one trial, with the columns the band needs
Trajectory load_trajectory(const fs::path& csv) {
  Trajectory tr = read_trajectory_csv(csv.string());
  if (!tr.has_column("time_s")) throw InputError(csv.string() + ": no column time_s in the header");
  if (!tr.has_column("angle_deg") && !tr.has_column("position_mm")) {
    throw InputError(csv.string() + ": no joint column (angle_deg or position_mm) in the header");
  }
  if (tr.rows() == 0) throw InputError(csv.string() + ": no data rows");
  return tr;
}

LoadedRun load_run(const std::string& dir) {
  LoadedRun run;
  run.dir = dir;
  if (!fs::is_directory(dir))
    throw InputError(dir + ": not a folder (expected a `pamsim run` output folder)");
  const fs::path summary_path = fs::path(dir) / "summary.json";
  if (!fs::is_regular_file(summary_path)) {
    throw InputError(dir +
                     ": not a run folder, no summary.json (expected a `pamsim run` output folder)");
  }
  const nlohmann::json summary = read_json(summary_path);
  if (!summary.is_object()) throw InputError(summary_path.string() + ": expected a JSON object");

  if (summary.contains("metrics")) {
    // repeated trials: aggregate metrics, one trajectory per trial_* folder (sorted by name)
    const nlohmann::json& metrics = summary["metrics"];
    if (!metrics.is_object())
      throw InputError(summary_path.string() + ": metrics must be an object");
    for (const auto& [name, m] : metrics.items()) {
      if (!m.is_object()) continue;
      MetricStats s;
      s.mean = m.contains("mean") ? number_or_nan(m["mean"]) : NAN;
      s.min = m.contains("min") ? number_or_nan(m["min"]) : NAN;
      s.max = m.contains("max") ? number_or_nan(m["max"]) : NAN;
      s.count = m.contains("count") && m["count"].is_number() ? m["count"].get<long>() : 0;
      run.metrics[name] = s;
    }
    std::vector<fs::path> trial_csvs;
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (entry.is_directory() && name.rfind("trial_", 0) == 0 &&
          fs::is_regular_file(entry.path() / "trajectory.csv")) {
        trial_csvs.push_back(entry.path() / "trajectory.csv");
      }
    }
    if (trial_csvs.empty()) {
      throw InputError(dir +
                       ": not a run folder, no trial_*/trajectory.csv beside its summary.json");
    }
    std::sort(trial_csvs.begin(), trial_csvs.end());
    for (const auto& csv : trial_csvs) run.trajectories.push_back(load_trajectory(csv));
  } else {
    // a single trial: its own numbers are the metrics, a band of one
    for (const auto& [name, v] : summary.items()) {
      if (name == "seed" || !(v.is_number() || v.is_null())) continue;
      MetricStats s;
      s.mean = s.min = s.max = number_or_nan(v);
      s.count = std::isfinite(s.mean) ? 1 : 0;
      run.metrics[name] = s;
    }
    const fs::path csv = fs::path(dir) / "trajectory.csv";
    if (!fs::is_regular_file(csv)) {
      throw InputError(
          dir +
          ": not a run folder, its summary.json has no metrics and there is no trajectory.csv");
    }
    run.trajectories.push_back(load_trajectory(csv));
  }
  return run;
}

// DIR's name, for the legend when no label is given
std::string default_label(const std::string& dir) {
  fs::path p = fs::path(dir).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  if (p.filename() == "." || p.filename() == ".." || p.empty()) {
    p = fs::absolute(p).lexically_normal();
    if (p.filename().empty()) p = p.parent_path();
  }
  const std::string name = p.filename().string();
  return name.empty() ? dir : name;
}

// a run folder's own name ("renders/model/" -> "model")
std::string folder_name(const std::string& dir) {
  fs::path p = fs::path(dir).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  if (p.filename() == "." || p.filename() == "..") p = fs::absolute(p).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  return p.filename().string();
}

// renders/compare_<A>_vs_<B>.png, like every command's default output under renders/ (named
// by both folders, so that a second comparison does not overwrite the first)
std::string default_out(const std::string& dir_a, const std::string& dir_b) {
  return "renders/compare_" + folder_name(dir_a) + "_vs_" + folder_name(dir_b) + ".png";
}

std::string format_stats(const MetricStats* s) {
  if (s == nullptr || !std::isfinite(s->mean)) return "-";
  char buf[96];
  if (s->min == s->max || !std::isfinite(s->min) || !std::isfinite(s->max)) {
    std::snprintf(buf, sizeof(buf), "%.4g", s->mean);
  } else {
    std::snprintf(buf, sizeof(buf), "%.4g [%.4g, %.4g]", s->mean, s->min, s->max);
  }
  return buf;
}

// metric | A mean [min, max] | B mean [min, max]; metrics of either run, sorted by name
void print_metrics_table(std::ostream& out, const LoadedRun& a, const std::string& label_a,
                         const LoadedRun& b, const std::string& label_b) {
  std::vector<std::string> names;
  for (const auto& [name, s] : a.metrics) names.push_back(name);
  for (const auto& [name, s] : b.metrics) {
    if (!a.metrics.count(name)) names.push_back(name);
  }
  std::sort(names.begin(), names.end());

  std::vector<std::array<std::string, 3>> rows;
  rows.push_back({"metric", label_a + " mean [min, max]", label_b + " mean [min, max]"});
  rows.push_back(
      {"trials", std::to_string(a.trajectories.size()), std::to_string(b.trajectories.size())});
  for (const auto& name : names) {
    const auto ia = a.metrics.find(name);
    const auto ib = b.metrics.find(name);
    rows.push_back({name, format_stats(ia == a.metrics.end() ? nullptr : &ia->second),
                    format_stats(ib == b.metrics.end() ? nullptr : &ib->second)});
  }
  std::array<std::size_t, 3> width{0, 0, 0};
  for (const auto& row : rows) {
    for (int c = 0; c < 3; ++c) width[c] = std::max(width[c], row[c].size());
  }
  for (const auto& row : rows) {
    out << row[0] << std::string(width[0] - row[0].size() + 2, ' ') << row[1]
        << std::string(width[1] - row[1].size() + 2, ' ') << row[2] << "\n";
  }
}

void compare(const CompareOptions& opt) {
  // both runs, then their bands on one plot
  const LoadedRun a = load_run(opt.dir_a);
  const LoadedRun b = load_run(opt.dir_b);
  std::string label_a = opt.label_a.empty() ? default_label(opt.dir_a) : opt.label_a;
  std::string label_b = opt.label_b.empty() ? default_label(opt.dir_b) : opt.label_b;
  if (label_a == label_b && opt.label_a.empty() && opt.label_b.empty()) {
    label_a = opt.dir_a;
    label_b = opt.dir_b;
  }
  std::vector<BandSeries> bands;
  for (const auto* run : {&a, &b}) {
    std::vector<const Trajectory*> ptrs;
    for (const auto& t : run->trajectories) ptrs.push_back(&t);
    try {
      bands.push_back(angle_band(ptrs, run == &a ? label_a : label_b));
    } catch (const std::invalid_argument&) {
      throw InputError(run->dir + ": its trials log different joints (angle_deg and position_mm)");
    }
  }
  // what the logs hold decides the plot: a hinge's angle or a slide's position, not both
  if (bands[0].quantity != bands[1].quantity) {
    throw InputError(opt.dir_b + ": logs the " + bands[1].unit + " " + bands[1].quantity +
                     " of a joint, " + opt.dir_a + " the " + bands[0].unit + " " +
                     bands[0].quantity + "; compare runs of one kind of joint");
  }
  const std::string out = opt.out.empty() ? default_out(opt.dir_a, opt.dir_b) : opt.out;
  if (is_stream_output(out)) {
    throw InputError("-o " + out + ": a plot is written to a file, not to a stream");
  }
  use_plot_formats(opt.plot_format);
  for (const std::string& format : plot_formats(opt.plot_format)) {
    refuse_existing_file(fs::path(out).replace_extension(format).string(), opt.force);
  }
  make_directories(fs::path(out).parent_path().empty() ? "."
                                                       : fs::path(out).parent_path().string());
  write_compare_plot(out, bands);

  // the metrics side by side
  print_metrics_table(std::cout, a, label_a, b, label_b);
  std::cerr << "pamsim: compare plot in " << out << "\n";
}

}  // namespace

void add_compare_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<CompareOptions>(
      app, "compare", "Compare two runs: angle bands on one plot, metrics side by side", compare);
  cmd->add_option("dir_a", opt->dir_a, "Output folder of a `pamsim run` (e.g. the model)")
      ->required();
  cmd->add_option("dir_b", opt->dir_b, "Output folder of another run (e.g. the fiber sensor)")
      ->required();
  // --out: its name before 0.3 (-o/--output names a file everywhere now)
  cmd->add_option("-o,--output,--out", opt->out,
                  "Plot file (default renders/compare_<DIR_A name>_vs_<DIR_B name>.png)");
  cmd->add_flag("--force", opt->force, "Replace an existing plot file");
  add_plot_format_option(cmd, &opt->plot_format);
  cmd->add_option("--label-a", opt->label_a, "Legend label of DIR_A (default: its folder name)");
  cmd->add_option("--label-b", opt->label_b, "Legend label of DIR_B (default: its folder name)");
}

}  // namespace pamsim
