// sweep_summary.cc: reading a sweep database into per-point statistics (report.h's
// summarize_sweep): the definition, then one pass over the trials in order, a point's
// metrics accumulated (Welford) over its trials that ran to the end.
#include "sim/sweep/report.h"
#include "sim/sweep/running_stats.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "base/no_value.h"
#include "sim/core/metrics.h"
#include "sim/sweep/sweep.h"

namespace pamsim {
namespace {

// A database cell as a TOML value (numbers exact, as the sweep wrote them).
std::string toml_value(const DbValue& v) {
  AxisValue a;
  if (v.kind == DbValue::Kind::kText) {
    a.kind = AxisValue::Kind::kString;
    a.text = v.text;
  } else {
    a.number = v.kind == DbValue::Kind::kNumber ? v.number : kNaN;
  }
  return a.toml();
}

// Index of a column by name; throws InputError if the table lacks it.
std::size_t column_of(const std::vector<std::string>& columns, const std::string& name,
                      const std::string& db) {
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c] == name) return c;
  }
  throw InputError(db + ": the trials table has no column " + name);
}

// A grid point's levels, as the sweep set them (the first axis varies slowest).
std::vector<std::string> grid_levels_of(const SweepSummary& sweep, std::int64_t point) {
  std::vector<std::string> values(sweep.axis_levels.size());
  std::int64_t rest = point;
  for (std::size_t a = sweep.axis_levels.size(); a-- > 0;) {
    const auto levels = static_cast<std::int64_t>(sweep.axis_levels[a].size());
    values[a] = sweep.axis_levels[a][static_cast<std::size_t>(rest % levels)];
    rest /= levels;
  }
  return values;
}

// The sweep's description from the database's canonical definition.
void read_definition(const ResultsDb& db, SweepSummary* out) {
  SweepSummary& sweep = *out;
  const auto def = nlohmann::json::parse(db.meta("definition"), nullptr, false);
  if (def.is_discarded() || !def.is_object()) {
    throw InputError(db.path() + ": the sweep definition is unreadable");
  }
  try {
    sweep.design = def.at("design").get<std::string>();
    sweep.seeds = def.at("seeds").get<std::int64_t>();
    sweep.base_scenario = def.at("base_scenario").get<std::string>();
    sweep.fixed = def.at("fixed").get<std::vector<std::string>>();
    sweep.points_total = sweep.design == "grid" ? 1 : def.at("samples").get<std::int64_t>();
    for (const auto& axis : def.at("axes")) {
      sweep.axis_keys.push_back(axis.at("key").get<std::string>());
      sweep.axis_log.push_back(axis.contains("range") && axis["range"].at("log").get<bool>());
      std::vector<std::string> levels = axis.at("values").get<std::vector<std::string>>();
      if (sweep.design == "grid") sweep.points_total *= static_cast<std::int64_t>(levels.size());
      sweep.axis_levels.push_back(std::move(levels));
      sweep.axis_cases.push_back(axis.value("cases", std::vector<std::vector<std::string>>{}));
    }
    for (const auto& r : def.value("randomize", nlohmann::json::array())) {
      sweep.randomize_keys.push_back(r.at("key").get<std::string>());
    }
  } catch (const nlohmann::json::exception& e) {
    throw InputError(db.path() + ": the sweep definition is incomplete (" + e.what() + ")");
  }
  sweep.trials_total = sweep.points_total * sweep.seeds;
}

// Where the summary's columns are in the trials table.
struct TrialColumns {
  std::size_t point = 0, status = 0;
  std::size_t mistrips = 0;  // past the end when the sweep has no reflex metrics
  std::vector<std::size_t> axes, metrics;
};

TrialColumns trial_columns_of(const ResultsDb& db, const SweepSummary& sweep) {
  const std::vector<std::string> columns = db.trial_columns();
  TrialColumns c;
  c.point = column_of(columns, "point", db.path());
  c.status = column_of(columns, "status", db.path());
  // a sweep without reflex metrics has no mistrips column: no trial mistripped
  const auto mistrips_at = std::find(columns.begin(), columns.end(), "mistrips");
  c.mistrips = static_cast<std::size_t>(mistrips_at - columns.begin());
  for (const auto& key : sweep.axis_keys) c.axes.push_back(column_of(columns, key, db.path()));
  for (const auto& name : sweep.metric_names) {
    c.metrics.push_back(column_of(columns, name, db.path()));
  }
  return c;
}

}  // namespace

SweepSummary summarize_sweep(const ResultsDb& db) {
  SweepSummary sweep;
  sweep.db_path = db.path();
  sweep.sweep_file = db.meta("sweep_file");
  sweep.base_path = db.meta("base_path");
  read_definition(db, &sweep);
  for (const auto& name : db.metric_columns()) {
    if (!is_timing_metric(name)) sweep.metric_names.push_back(name);
  }

  const TrialColumns col = trial_columns_of(db, sweep);
  // one pass in trial order; a point's trials are consecutive
  PointSummary current;
  std::vector<Accumulator> acc;
  auto close_point = [&] {
    if (current.trials == 0) return;
    for (const auto& a : acc) current.metrics.push_back(a.stats());
    sweep.points.push_back(std::move(current));
    current = PointSummary{};
  };
  db.for_each_trial([&](const std::vector<DbValue>& row) {
    const auto point = static_cast<std::int64_t>(row[col.point].number);
    if (current.trials > 0 && point != current.point) close_point();
    if (current.trials == 0) {
      current.point = point;
      if (sweep.design == "grid") {  // the levels exactly as the sweep set them (types kept)
        current.axis_values = grid_levels_of(sweep, point);
      } else {  // random and lhs sample float ranges
        for (std::size_t c : col.axes) current.axis_values.push_back(toml_value(row[c]));
      }
      acc.assign(col.metrics.size(), Accumulator{});
    }
    ++current.trials;
    ++sweep.trials_stored;
    if (row[col.status].text != "ok") {
      ++sweep.trials_not_ok;
      return;
    }
    ++current.ok;
    if (col.mistrips < row.size() && row[col.mistrips].kind == DbValue::Kind::kNumber &&
        row[col.mistrips].number > 0) {
      ++current.with_mistrips;
    }
    for (std::size_t m = 0; m < col.metrics.size(); ++m) {
      const DbValue& v = row[col.metrics[m]];
      if (v.kind == DbValue::Kind::kNumber && std::isfinite(v.number)) acc[m].add(v.number);
    }
  });
  close_point();
  return sweep;
}

}  // namespace pamsim
