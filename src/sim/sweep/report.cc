// report.cc: see report.h.
#include "sim/sweep/report.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "base/no_value.h"
#include "base/config_reader.h"
#include "sim/io/outputs.h"
#include "sim/core/metrics.h"
#include "sim/scenario/scenario_file.h"
#include "sim/scenario/scenario_key_docs.h"
#include "sim/sweep/running_stats.h"
#include "sim/sweep/sweep.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;
constexpr const char* kMistripRate = "mistrip_rate";

// A TOML value as a person reads it: a string without its quotes ('x' or "x"), anything
// else as written.
std::string unquoted(const std::string& toml) {
  try {
    const toml::table t = toml::parse("v = " + toml);
    if (const auto text = t["v"].value<std::string>()) return *text;
  } catch (const toml::parse_error&) {
  }
  return toml;
}

// "trigger threshold V_thr, Eq. (12) [mm/s], log scale (reflex.v_thr_mm_s)": an axis's
// meaning and unit from the scenario keys' documentation, and the key itself
std::string axis_label(const std::string& key, bool log_scale) {
  std::string label;
  if (const KeyDoc* d = scenario_key_doc(key)) {
    label = d->meaning.rfind("the ", 0) == 0 ? d->meaning.substr(4) : d->meaning;
    if (!d->unit.empty()) label += " [" + d->unit + "]";
  }
  if (log_scale) label += label.empty() ? "log scale" : ", log scale";
  return label.empty() ? key : label + " (" + key + ")";
}

// A level for a tick label: numbers to 3 significant digits, strings without quotes.
std::string level_label(const std::string& toml) {
  double v;
  const auto r = std::from_chars(toml.data(), toml.data() + toml.size(), v);
  if (r.ec == std::errc() && r.ptr == toml.data() + toml.size()) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.3g", v);
    return buf;
  }
  return unquoted(toml);
}

std::string number_text(double v) {
  if (!std::isfinite(v)) return "";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}

// The value shown for a point: a metric's mean, or the mistrip rate.
// A grid's points per level pair of its first two axes: the other axes' levels multiplied
std::int64_t points_per_cell(const SweepSummary& sweep) {
  std::int64_t inner = 1;
  for (std::size_t a = 2; a < sweep.axis_levels.size(); ++a) {
    inner *= static_cast<std::int64_t>(sweep.axis_levels[a].size());
  }
  return inner;
}

double point_value(const SweepSummary& sweep, const PointSummary& p, const std::string& metric) {
  if (metric == kMistripRate) return p.mistrip_rate();
  const int m = sweep.metric_index(metric);
  return m < 0 ? kNaN : p.metrics[static_cast<std::size_t>(m)].mean;
}

}  // namespace

double PointSummary::mistrip_rate() const {
  return ok > 0 ? static_cast<double>(with_mistrips) / ok : kNaN;
}

int SweepSummary::metric_index(const std::string& name) const {
  for (std::size_t i = 0; i < metric_names.size(); ++i) {
    if (metric_names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

std::vector<const PointSummary*> best_points(const SweepSummary& sweep, const std::string& metric,
                                             std::size_t k) {
  std::vector<std::pair<double, const PointSummary*>> ranked;
  const int m = sweep.metric_index(metric);
  for (const PointSummary& p : sweep.points) {
    if (p.ok != sweep.seeds || p.with_mistrips != 0) continue;
    if (m >= 0 && p.metrics[static_cast<std::size_t>(m)].count != sweep.seeds) continue;
    const double v = point_value(sweep, p, metric);
    if (std::isfinite(v)) ranked.emplace_back(v, &p);
  }
  // by value, ties by point number (the points are in point order)
  std::stable_sort(ranked.begin(), ranked.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<const PointSummary*> best;
  for (std::size_t i = 0; i < ranked.size() && i < k; ++i) best.push_back(ranked[i].second);
  return best;
}

const PointSummary* best_point(const SweepSummary& sweep, const std::string& metric) {
  const std::vector<const PointSummary*> best = best_points(sweep, metric, 1);
  return best.empty() ? nullptr : best.front();
}

std::pair<std::size_t, std::size_t> grid_cell_of(const SweepSummary& sweep, std::int64_t point) {
  const std::int64_t inner = points_per_cell(sweep);  // row-major, first axis slowest
  const auto ny = static_cast<std::int64_t>(sweep.axis_levels[1].size());
  return {static_cast<std::size_t>(point / inner / ny),
          static_cast<std::size_t>(point / inner % ny)};
}

std::string best_criterion(const SweepSummary& sweep, const std::string& metric) {
  return "smallest mean " + metric + " over the seeds, among points where all " +
         std::to_string(sweep.seeds) + " seeds ran ok with zero mistrips and a defined " + metric +
         " (ties: the lowest point number)";
}

std::string metric_label(const std::string& name) {
  if (name == kMistripRate) return "mistrip rate [fraction of seeds]";
  static const std::pair<const char*, const char*> kUnits[] = {
      {"_mm_s", "mm/s"}, {"_deg", "deg"}, {"_mm", "mm"}, {"_pct", "% of length"},
      {"_MPa", "MPa"},   {"_N", "N"},     {"_s", "s"}};
  std::string base = name, unit;
  for (const auto& [suffix, u] : kUnits) {
    if (ends_with(name, suffix)) {
      base = name.substr(0, name.size() - std::string(suffix).size());
      unit = u;
      break;
    }
  }
  for (char& c : base) c = c == '_' ? ' ' : c;
  return unit.empty() ? base : base + " [" + unit + "]";
}

std::vector<std::string> point_overrides(const SweepSummary& sweep, const PointSummary& point) {
  std::vector<std::string> overrides = sweep.fixed;
  for (std::size_t a = 0; a < sweep.axis_keys.size(); ++a) {
    const std::vector<std::string>& levels = sweep.axis_levels[a];
    const auto level = std::find(levels.begin(), levels.end(), point.axis_values[a]);
    if (sweep.axis_cases[a].empty()) {
      overrides.push_back(sweep.axis_keys[a] + "=" + point.axis_values[a]);
      continue;
    }
    if (level == levels.end()) {
      throw InputError(sweep.db_path + ": case " + point.axis_values[a] + " of axis " +
                       sweep.axis_keys[a] + " is not in the sweep's definition");
    }
    const auto& set = sweep.axis_cases[a][static_cast<std::size_t>(level - levels.begin())];
    overrides.insert(overrides.end(), set.begin(), set.end());
  }
  return overrides;
}

std::string point_scenario_toml(const SweepSummary& sweep, const PointSummary& point,
                                const std::string& scenario_dir, const std::string& header) {
  const std::vector<std::string> overrides = point_overrides(sweep, point);
  return resolved_scenario_toml(sweep.base_scenario, sweep.base_path, overrides, scenario_dir,
                                header);
}

std::string points_csv(const SweepSummary& sweep, const std::string& metric, bool all_columns) {
  // the metrics shown: all, or the headline ones the sweep has and the report's own
  std::vector<int> shown;
  if (all_columns) {
    for (std::size_t m = 0; m < sweep.metric_names.size(); ++m)
      shown.push_back(static_cast<int>(m));
  } else {
    std::vector<std::string> names = kPointsCsvMetrics;
    if (std::find(names.begin(), names.end(), metric) == names.end()) names.push_back(metric);
    for (const std::string& name : names) {
      const int m = sweep.metric_index(name);
      if (m >= 0) shown.push_back(m);
    }
  }
  std::string out = "point";
  for (const auto& key : sweep.axis_keys) out += "," + key;
  out += ",trials,ok,mistrip_rate";
  for (const int m : shown) {
    const std::string& name = sweep.metric_names[static_cast<std::size_t>(m)];
    out += all_columns
               ? "," + name + "_mean," + name + "_std," + name + "_min," + name + "_max"
               : "," + name + "_mean," + name + "_sd," + name + "_ci95_low," + name + "_ci95_high";
  }
  out += "\n";
  for (const PointSummary& p : sweep.points) {
    out += std::to_string(p.point);
    for (const auto& v : p.axis_values) out += "," + unquoted(v);
    out += "," + std::to_string(p.trials) + "," + std::to_string(p.ok) + "," +
           number_text(p.mistrip_rate());
    for (const int m : shown) {
      const MetricStats& s = p.metrics[static_cast<std::size_t>(m)];
      if (all_columns) {
        out += "," + number_text(s.mean) + "," + number_text(s.std) + "," + number_text(s.min) +
               "," + number_text(s.max);
      } else {
        const double half = ci95_half_width(s.std, s.count);
        out += "," + number_text(s.mean) + "," + number_text(s.std) + "," +
               number_text(s.mean - half) + "," + number_text(s.mean + half);
      }
    }
    out += "\n";
  }
  return out;
}

namespace {

// random and lhs: every point where it lies
void scatter_points(const SweepSummary& sweep, const std::string& metric, const PointSummary* mark,
                    HeatMap* out) {
  HeatMap& map = *out;
  map.scattered = true;
  map.x_log = sweep.axis_log[0];
  map.y_log = sweep.axis_log[1];
  for (const PointSummary& p : sweep.points) {
    map.x.push_back(std::strtod(p.axis_values[0].c_str(), nullptr));
    map.y.push_back(std::strtod(p.axis_values[1].c_str(), nullptr));
    map.values.push_back(point_value(sweep, p, metric));
    if (&p == mark) {
      map.mark_x = map.x.back();
      map.mark_y = map.y.back();
    }
  }
}

// grid: a cell per level pair of the first two axes, averaging the other axes' points
void grid_cells(const SweepSummary& sweep, const std::string& metric, const PointSummary* mark,
                HeatMap* out) {
  HeatMap& map = *out;
  const bool rate = metric == kMistripRate;
  const std::size_t nx = sweep.axis_levels[0].size(), ny = sweep.axis_levels[1].size();
  if (sweep.axis_keys.size() > 2) map.title += " (cells average the other axes)";
  for (const auto& l : sweep.axis_levels[0]) map.x_levels.push_back(level_label(l));
  for (const auto& l : sweep.axis_levels[1]) map.y_levels.push_back(level_label(l));
  std::vector<Accumulator> cells(nx * ny);
  std::vector<double> seed_sd(nx * ny, kNaN);  // a cell of one point: its SD over the seeds
  const int m = sweep.metric_index(metric);
  for (const PointSummary& p : sweep.points) {
    const auto [ix, iy] = grid_cell_of(sweep, p.point);
    const double v = point_value(sweep, p, metric);
    if (std::isfinite(v)) cells[iy * nx + ix].add(v);
    if (m >= 0) seed_sd[iy * nx + ix] = p.metrics[static_cast<std::size_t>(m)].std;
    if (&p == mark) {
      map.mark_x = static_cast<double>(ix);
      map.mark_y = static_cast<double>(iy);
    }
  }
  map.cell_format = rate ? "%.1f" : "%.3g";
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const MetricStats st = cells[c].stats();
    map.cells.push_back(st.mean);
    // the spread beside the mean: over the seeds, or (cells averaging other axes) over the
    // points' means
    const double sd = points_per_cell(sweep) == 1 ? seed_sd[c] : st.std;
    char text[64];
    if (rate || !std::isfinite(sd)) {
      std::snprintf(text, sizeof(text), map.cell_format.c_str(), st.mean);
    } else {
      std::snprintf(text, sizeof(text), "%.3g ± %.2g", st.mean, sd);
    }
    map.cell_texts.push_back(text);
  }
}

}  // namespace

HeatMap sweep_heat_map(const SweepSummary& sweep, const std::string& metric,
                       const PointSummary* mark, const std::string& best_metric) {
  if (sweep.axis_keys.size() < 2) {
    throw InputError(sweep.db_path + ": heat maps need two axes, the sweep has " +
                     std::to_string(sweep.axis_keys.size()));
  }
  HeatMap map;
  map.x_label = axis_label(sweep.axis_keys[0], sweep.axis_log[0]);
  map.y_label = axis_label(sweep.axis_keys[1], sweep.axis_log[1]);
  const bool rate = metric == kMistripRate;
  map.value_label = rate ? metric_label(metric) : metric_label(metric) + ", mean over the seeds";
  map.title = metric_label(metric) + (rate ? "" : ": mean ± SD") + " over " +
              std::to_string(sweep.seeds) + " seeds per point";
  if (!rate && sweep.axis_keys.size() > 2) {
    map.title = metric_label(metric) + ": mean ± SD over the points of the other axes";
  }
  if (sweep.trials_stored < sweep.trials_total) {
    map.title += "; INCOMPLETE: " + std::to_string(sweep.trials_stored) + " of " +
                 std::to_string(sweep.trials_total) + " trials stored";
  }
  map.missing_label = "no seed ran ok (diverged, failed or not run)";
  if (rate) {
    map.value_min = 0;
    map.value_max = 1;
  }
  if (mark) {
    map.has_mark = true;
    map.mark_label = "best (smallest mean " + best_metric + ", no mistrips; ties: lowest point)";
  }

  if (sweep.design != "grid") {
    scatter_points(sweep, metric, mark, &map);
    return map;
  }
  grid_cells(sweep, metric, mark, &map);
  return map;
}
std::vector<std::string> default_table_metrics(const SweepSummary& sweep,
                                               const std::string& metric) {
  std::vector<std::string> names;
  for (const std::string& name : kPointsCsvMetrics) {
    if (sweep.metric_index(name) >= 0) names.push_back(name);
  }
  if (std::find(names.begin(), names.end(), metric) == names.end()) names.push_back(metric);
  return names;
}

std::string markdown_cell(const std::string& text) {
  std::string cell;
  for (const char c : text) {
    if (c == '|' || c == '\\') cell += '\\';
    cell += c == '\n' ? ' ' : c;
  }
  return cell;
}

std::string points_markdown(const SweepSummary& sweep, const std::vector<std::string>& metrics) {
  std::vector<int> shown;
  for (const std::string& name : metrics) {
    shown.push_back(sweep.metric_index(name));
    if (shown.back() < 0) throw InputError("--table: the sweep has no metric " + name);
  }
  std::string out = "|", rule = "|";
  for (const auto& key : sweep.axis_keys) out += " " + markdown_cell(key) + " |";
  out += " ok / trials |";
  for (const std::string& name : metrics) out += " " + metric_label(name) + " |";
  for (std::size_t c = 0; c < sweep.axis_keys.size() + 1 + metrics.size(); ++c) rule += " --- |";
  out += "\n" + rule + "\n";
  char buf[96];
  for (const PointSummary& p : sweep.points) {
    out += "|";
    for (const auto& v : p.axis_values) out += " " + markdown_cell(unquoted(v)) + " |";
    out += " " + std::to_string(p.ok) + " / " + std::to_string(p.trials) + " |";
    for (const int m : shown) {
      const MetricStats& s = p.metrics[static_cast<std::size_t>(m)];
      std::snprintf(buf, sizeof(buf), "%.4g [%.4g, %.4g]", s.mean, s.min, s.max);
      out += s.count == 0 ? std::string(" - |") : " " + std::string(buf) + " |";
    }
    out += "\n";
  }
  return out;
}

std::vector<std::string> grid_edges_of(const SweepSummary& sweep, const PointSummary& point) {
  std::vector<std::string> edges;
  if (sweep.design != "grid") return edges;
  for (std::size_t a = 0; a < sweep.axis_keys.size(); ++a) {
    const std::vector<std::string>& levels = sweep.axis_levels[a];
    double v = 0;
    const std::string& text = point.axis_values[a];
    const auto parsed = std::from_chars(text.data(), text.data() + text.size(), v);
    if (!sweep.axis_cases[a].empty() || levels.size() < 2 || parsed.ec != std::errc()) continue;
    if (text == levels.front() || text == levels.back()) {
      edges.push_back(sweep.axis_keys[a] + " = " + text + " (the grid's " +
                      (text == levels.front() ? "lowest" : "highest") + " level)");
    }
  }
  return edges;
}

}  // namespace pamsim
