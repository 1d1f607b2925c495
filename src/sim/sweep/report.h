// report.h: what a sweep database says, per grid point: mean, spread (sample standard
// deviation), min and max of every metric over the seeds that ran ok, the mistrip rate
// (fraction of those seeds with a trigger before the impact), and the best point under a
// stated criterion, written back as a ready-to-run scenario. Reads the database in trial
// order and keeps one summary per point, never the trials.
#pragma once

#include <cstdint>
#include <utility>
#include <string>
#include <vector>

#include "sim/io/plot.h"
#include "sim/sweep/results_db.h"

namespace pamsim {

struct MetricStats {
  int count = 0;                               // seeds where the metric is defined
  double mean = 0, std = 0, min = 0, max = 0;  // NaN when count == 0 (std NaN when count < 2)
};

struct PointSummary {
  std::int64_t point = 0;
  std::vector<std::string> axis_values;  // as TOML values (numbers exact), one per axis
  int trials = 0;                        // stored
  int ok = 0;                            // of those, status "ok"
  int with_mistrips = 0;                 // of the ok ones, with mistrips > 0
  std::vector<MetricStats> metrics;      // one per SweepSummary::metric_names
  double mistrip_rate() const;           // with_mistrips / ok; NaN if none ran ok
};

struct SweepSummary {
  std::string db_path, sweep_file, base_path, design;
  std::string base_scenario;       // its text at the time of the sweep
  std::vector<std::string> fixed;  // "key=value" at every point
  std::int64_t seeds = 0, points_total = 0, trials_total = 0;
  std::int64_t trials_stored = 0, trials_not_ok = 0;
  std::vector<std::string> axis_keys;
  std::vector<bool> axis_log;
  std::vector<std::vector<std::string>> axis_levels;  // grid designs: each axis's values
  // a case axis's sets ("key=value" per case, in its levels' order); empty for a key's axis
  std::vector<std::vector<std::vector<std::string>>> axis_cases;
  std::vector<std::string> randomize_keys;  // [[randomize]]: drawn per trial, a column each
  std::vector<std::string> metric_names;
  std::vector<PointSummary> points;  // stored points, in point order

  // index of a metric, or -1
  int metric_index(const std::string& name) const;
};

// Throws InputError if the database is not a sweep database.
SweepSummary summarize_sweep(const ResultsDb& db);

// The criterion: among points whose every seed is stored, ran ok with zero mistrips and has
// `metric` defined, the smallest mean of `metric`. nullptr if no point qualifies.
const PointSummary* best_point(const SweepSummary& sweep, const std::string& metric);
// The first k points by the same criterion, best first (fewer when fewer qualify).
std::vector<const PointSummary*> best_points(const SweepSummary& sweep, const std::string& metric,
                                             std::size_t k);
// A grid design's cell of `point` on its first two axes: (level of axis 0, level of axis 1).
std::pair<std::size_t, std::size_t> grid_cell_of(const SweepSummary& sweep, std::int64_t point);
std::string best_criterion(const SweepSummary& sweep, const std::string& metric);
// A metric's name for a plot, its unit from its suffix: "peak drop [deg]",
// "recovery time [s]", "mistrip rate [fraction of seeds]".
std::string metric_label(const std::string& name);

// "key=value" overrides that make the base scenario the point's: the sweep's fixed keys,
// then the point's axis values (TOML, types kept).
std::vector<std::string> point_overrides(const SweepSummary& sweep, const PointSummary& point);

// The base scenario with the sweep's fixed keys and the point's axis values set, its file
// paths rewritten relative to `scenario_dir` (where it will be written), as TOML text with a
// header saying where it came from (resolved_scenario_toml, scenario_file.h).
std::string point_scenario_toml(const SweepSummary& sweep, const PointSummary& point,
                                const std::string& scenario_dir, const std::string& header);

// points.csv: point, the axis values, trials, ok, mistrip_rate, then for each of
// kPointsCsvMetrics the sweep has, and `metric` (the report's), <metric>_mean, _sd,
// _ci95_low, _ci95_high (Student's t over the seeds where it is defined). With
// `all_columns`, every metric (timing left out) with _mean, _std, _min, _max instead, the
// table of pamsim 0.2. Every trial's values stay in the database (pamsim export).
inline const std::vector<std::string> kPointsCsvMetrics = {
    "peak_drop_deg",           "recovery_time_s", "first_trigger_time_s", "mistrips",
    "retriggers_after_impact", "mass_retained",   "length_est_rmse_pct"};
std::string points_csv(const SweepSummary& sweep, const std::string& metric = "peak_drop_deg",
                       bool all_columns = false);

// The numeric grid axes on whose first or last level `point` lies, each as "key = value (the
// grid's lowest|highest level)": a best point there may have a better one beyond the grid.
// Empty for a random or lhs design and for case or text axes.
std::vector<std::string> grid_edges_of(const SweepSummary& sweep, const PointSummary& point);

// table.md: the points as a Markdown table a paper's table of conditions reads like: one row
// per point (its axes' values: a case axis's case names), the seeds that ran ok of those
// stored, and each of `metrics` as "mean [min, max]" over those seeds (4 significant
// digits; "-" where none has it). Throws InputError naming a metric the sweep lacks.
std::string points_markdown(const SweepSummary& sweep, const std::vector<std::string>& metrics);
// `text` as one cell of a Markdown table: '|' and '\\' escaped, a line break as a space
// (a case's name may hold any of them).
std::string markdown_cell(const std::string& text);
// The metrics table.md shows unless asked: kPointsCsvMetrics the sweep has, and `metric`.
std::vector<std::string> default_table_metrics(const SweepSummary& sweep,
                                               const std::string& metric);

// A heat map of `metric` (or "mistrip_rate") over the first two axes, with `best` (chosen
// on `best_metric`) marked if not null; on a grid with more axes each cell averages the
// points that share its two levels. Throws InputError if the sweep has fewer than two axes.
HeatMap sweep_heat_map(const SweepSummary& sweep, const std::string& metric,
                       const PointSummary* best, const std::string& best_metric);

}  // namespace pamsim
