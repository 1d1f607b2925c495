// report.cc: `pamsim report DB [--metric NAME] [--out DIR]`: reads a sweep database and
// writes, in DIR (default: the database's folder):
//   points.csv                per point: axis values, mean/std/min/max of every metric
//   table.md                  the points as a Markdown table (--table: its metrics)
//   heatmap_mistrip_rate.png, heatmap_peak_drop_deg.png, heatmap_recovery_time_s.png
//                             (and heatmap_<NAME>.png) over the first two axes
//   best.toml                 the best point (report.h's criterion on NAME, default
//                             peak_drop_deg) as a scenario: pamsim run DIR/best.toml
// and prints the criterion and the best point.
#include "sim/sweep/report.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/cli/report_folder.h"
#include "sim/cli/report_page.h"
#include "sim/optimize/tune_html.h"
#include "sim/io/html_page.h"
#include "sim/io/outputs.h"
#include "sim/io/plot.h"
#include "sim/io/provenance.h"
#include "sim/io/staged_outputs.h"
#include "sim/optimize/tune_outputs.h"

namespace pamsim {
namespace {

struct ReportOptions {
  std::string db;
  std::string metric = "peak_drop_deg";
  std::string out;
  bool force = false;
  bool no_plot = false;
  std::string plot_format = "png";
  bool all_columns = false;
  bool html = false;                      // --html: report.html beside the other outputs
  std::vector<std::int64_t> html_points;  // --html-points: more points replayed on it
  std::vector<std::string> table;         // table.md's metrics (empty: default_table_metrics)
};

const std::vector<std::string> kSweepReportOutputs = [] {
  std::vector<std::string> names = {"points.csv", "table.md", "best.toml", kReportPageFile,
                                    kProvenanceFile};
  for (const std::string& plot : plot_file_names({"heatmap_*.png"})) names.push_back(plot);
  return names;
}();

// provenance.json of a report: the database it read and the command line.
void write_report_provenance(const ReportOptions& opt, const StagedOutputs& staged,
                             std::chrono::steady_clock::time_point started,
                             const std::string& started_utc) {
  Provenance p;
  p.command = "report";
  p.from = opt.db;  // what it was made from
  p.started_utc = started_utc;
  write_provenance(staged.path(kProvenanceFile), p, started);
}

std::string stats_text(const MetricStats& m) {
  char buf[128];
  std::snprintf(buf, sizeof(buf), "%.4g +- %.2g (min %.4g, max %.4g, n %d)", m.mean,
                std::isfinite(m.std) ? m.std : 0.0, m.min, m.max, m.count);
  return buf;
}

// --out, or the database's folder
std::string report_folder(const ReportOptions& opt) {
  if (!opt.out.empty()) return opt.out;
  const std::string folder = std::filesystem::path(opt.db).parent_path().string();
  return folder.empty() ? "." : folder;
}

// A tuning database (pamsim tune): its evaluations, best setting and figures.
void report_tune(const ReportOptions& opt) {
  const TuneDb db = TuneDb::open_existing(opt.db);
  const TuneDefinition def = tune_definition_from_db(db);
  const std::vector<TuneEvaluation> history = db.evaluations();
  const std::string out = report_folder(opt);
  std::vector<std::string> outputs = kTuneReportOutputs;
  outputs.push_back(kReportPageFile);
  if (!opt.force) refuse_earlier_outputs(out, outputs);
  use_plot_formats(opt.plot_format);
  const bool plots = plots_wanted(opt.no_plot);
  StagedOutputs staged(out, outputs);
  staged.write([&] {
    write_tune_outputs(def, history, staged, plots);
    if (!opt.html) return;
    const std::string footer =
        database_footer(opt.db, db.meta("pamsim_version"), db.meta("git_commit"), "");
    write_file_atomically(staged.path(kReportPageFile),
                          tune_report_html(def, history, opt.db, footer));
  });
  staged.publish();
  const TuneEvaluation* best = best_evaluation(history);
  std::cout << "tuning: " << def.file << " (" << history.size() << " evaluations stored)\n"
            << "best: evaluation " << best->index
            << (best->violation == 0.0 ? "" : " (none feasible)");
  for (std::size_t i = 0; i < def.parameters.size(); ++i) {
    std::cout << ", " << def.parameters[i].key << " = " << format_value(best->values[i]);
  }
  std::cout << "; " << def.objectives[0].metric << " " << format_value(best->objectives[0])
            << "\noutputs: " << out << "/{best.toml,evaluations.csv,convergence.png"
            << (def.objectives.size() > 1 ? ",pareto.csv,pareto.png" : "") << "}\n";
}

// The best point by --metric: printed, and best.toml written; nullptr if none qualifies.
const PointSummary* report_best_point(const ReportOptions& opt, const SweepSummary& sweep,
                                      const StagedOutputs& staged, const std::string& out) {
  const PointSummary* best = best_point(sweep, opt.metric);
  std::cout << "criterion: " << best_criterion(sweep, opt.metric) << "\n";
  if (!best) {
    std::cout << "best: no point meets the criterion\n";
    return nullptr;
  }
  std::string setting;
  for (std::size_t a = 0; a < sweep.axis_keys.size(); ++a) {
    setting += (a ? ", " : "") + sweep.axis_keys[a] + " = " + best->axis_values[a];
  }
  std::cout << "best: point " << best->point << ": " << setting << "\n";
  for (const std::string& edge : grid_edges_of(sweep, *best)) {
    std::cout << "  warning: the best point lies on the grid's edge, " << edge
              << ": a better one may lie beyond it (widen that axis's range)\n";
  }
  for (const std::string& name :
       {opt.metric, std::string("recovery_time_s"), std::string("first_trigger_time_s"),
        std::string("impact_time_s")}) {
    const int m = sweep.metric_index(name);
    if (m >= 0) std::cout << "  " << name << " " << stats_text(best->metrics[m]) << "\n";
  }
  const std::string header =
      "# Best setting of the sweep " + sweep.sweep_file + " (database " + opt.db + "):\n# " +
      best_criterion(sweep, opt.metric) + ".\n# Point " + std::to_string(best->point) + ": " +
      setting + ".\n# Written by pamsim report from the base scenario " + sweep.base_path + ".\n\n";
  write_file_atomically(staged.path("best.toml"), point_scenario_toml(sweep, *best, out, header));
  std::cout << "  scenario: " << out << "/best.toml (pamsim run " << out << "/best.toml)\n";
  return best;
}

// The headline metrics the sweep has (mistrip rate, peak drop, recovery time) and --metric
std::vector<std::string> heat_map_metrics(const ReportOptions& opt, const SweepSummary& sweep) {
  std::vector<std::string> maps;
  for (const std::string& metric : {std::string("mistrip_rate"), std::string("peak_drop_deg"),
                                    std::string("recovery_time_s"), opt.metric}) {
    const bool listed = std::find(maps.begin(), maps.end(), metric) != maps.end();
    // the mistrip rate comes from the reflex metrics' mistrips count
    const bool has = sweep.metric_index(metric == "mistrip_rate" ? "mistrips" : metric) >= 0;
    if (!listed && has) maps.push_back(metric);
  }
  return maps;
}

// A heat map of each headline metric the sweep has (mistrip rate, peak drop, recovery time)
// and of --metric, over the first two axes; false (and says why) when there are none.
bool write_heat_maps(const ReportOptions& opt, const SweepSummary& sweep, const PointSummary* best,
                     const StagedOutputs& staged, bool plots) {
  if (!plots) {
    std::cout << "heat maps: none (no plots)\n";
    return false;
  }
  if (sweep.axis_keys.size() < 2) {
    std::cout << "heat maps: none (the sweep has one axis; see points.csv)\n";
    return false;
  }
  for (const auto& metric : heat_map_metrics(opt, sweep)) {
    write_heatmap(staged.path("heatmap_" + metric + ".png"),
                  sweep_heat_map(sweep, metric, best, opt.metric));
  }
  return true;
}

// A command's output folder (report_folder.h): its page, DIR/report.html (or in --out)
void report_folder_page(const ReportOptions& opt) {
  if (!opt.html) throw InputError(opt.db + ": a folder; its page needs --html");
  const std::string out = opt.out.empty() ? opt.db : opt.out;
  if (!opt.force) refuse_earlier_outputs(out, {kReportPageFile});
  const std::string page = folder_page_html(opt.db);
  make_directories(out);
  write_file_atomically((std::filesystem::path(out) / kReportPageFile).string(), page);
  std::cout << "page: " << out << "/report.html\n";
}

void report(const ReportOptions& opt) {
  if (!opt.html_points.empty() && !opt.html) throw InputError("--html-points needs --html");
  const bool a_sweep = !std::filesystem::is_directory(opt.db) && !TuneDb::is_tune_database(opt.db);
  if (!opt.html_points.empty() && !a_sweep) {
    throw InputError(opt.db +
                     ": --html-points replays a sweep's points; this is no sweep database");
  }
  if (std::filesystem::is_directory(opt.db)) return report_folder_page(opt);
  if (TuneDb::is_tune_database(opt.db)) return report_tune(opt);
  const auto started = std::chrono::steady_clock::now();
  const std::string started_utc = utc_timestamp();
  const ResultsDb db = ResultsDb::open_existing(opt.db);
  const SweepSummary sweep = summarize_sweep(db);
  std::string names;
  for (const auto& n : sweep.metric_names) names += (names.empty() ? "" : ", ") + n;
  if (sweep.metric_index(opt.metric) < 0) {
    throw InputError("--metric " + opt.metric + ": not a sweep metric (one of " + names + ")");
  }
  for (const std::string& metric : opt.table) {
    if (sweep.metric_index(metric) < 0) {
      throw InputError("--table " + metric + ": not a sweep metric (one of " + names + ")");
    }
  }
  asked_points(sweep, opt.html_points, opt.db);  // refused before anything is written
  const std::string out = report_folder(opt);
  if (!opt.force) refuse_earlier_outputs(out, kSweepReportOutputs);
  use_plot_formats(opt.plot_format);
  const bool plots = plots_wanted(opt.no_plot);
  // written together: a failure half way leaves an earlier report as it was
  StagedOutputs staged(out, kSweepReportOutputs);
  staged.write([&] {
    std::cout << "sweep: " << sweep.sweep_file << " (" << sweep.design << ", " << sweep.points_total
              << " points x " << sweep.seeds << " seeds; " << sweep.trials_stored << " of "
              << sweep.trials_total << " trials stored, " << sweep.trials_not_ok
              << " diverged or failed)\n";
    write_file_atomically(staged.path("points.csv"),
                          points_csv(sweep, opt.metric, opt.all_columns));
    const std::vector<std::string> table =
        opt.table.empty() ? default_table_metrics(sweep, opt.metric) : opt.table;
    write_file_atomically(staged.path("table.md"), points_markdown(sweep, table));

    const PointSummary* best = report_best_point(opt, sweep, staged, out);
    if (opt.html) {
      write_file_atomically(staged.path(kReportPageFile),
                            sweep_page_html(db, sweep, opt.db, opt.metric,
                                            heat_map_metrics(opt, sweep), opt.html_points));
      std::cout << "page: " << out << "/report.html\n";
    }
    if (!write_heat_maps(opt, sweep, best, staged, plots)) return;
    std::cout << "outputs: " << out << "/{points.csv,table.md,heatmap_*.png"
              << (best ? ",best.toml" : "") << "}\n";
  });
  staged.write([&] { write_report_provenance(opt, staged, started, started_utc); });
  staged.publish();
}

}  // namespace

void add_report_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<ReportOptions>(
      app, "report",
      "Per-point statistics, heat maps and the best setting of a sweep database (or a "
      "tuning database's evaluations, best setting, convergence and Pareto front)",
      report);
  cmd->add_option("db", opt->db,
                  "Sweep or tuning database (from pamsim sweep / tune), or with --html a "
                  "command's output folder (validate, identify)")
      ->required();
  cmd->add_option("--metric", opt->metric,
                  "Metric to minimise for the best setting (default peak_drop_deg)");
  cmd->add_option("--out", opt->out, "Output folder (default: the database's folder)");
  cmd->add_flag("--force", opt->force, "Replace an earlier report's files in the folder");
  cmd->add_flag("--all-columns", opt->all_columns,
                "points.csv with mean, std, min, max of every metric (default: mean, SD and 95 % "
                "CI of the headline metrics)");
  cmd->add_flag("--html", opt->html,
                "Also report.html: one self-contained page (heat maps whose cells show their "
                "points' metrics, the best points' trials replayed, every point's replay line)");
  cmd->add_option("--html-points", opt->html_points,
                  "With --html: these points' trials replayed on the page too (point numbers, "
                  "comma-separated)")
      ->delimiter(',');
  cmd->add_flag("--no-plot", opt->no_plot, "Write no heat maps or figures (gnuplot not needed)");
  cmd->add_option("--table", opt->table,
                  "Metrics of table.md, comma-separated (default: the headline metrics the sweep "
                  "has, and --metric)")
      ->delimiter(',');
  add_plot_format_option(cmd, &opt->plot_format);
}

}  // namespace pamsim
