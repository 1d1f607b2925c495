// sweep_file.cc: reading a sweep file (sweep.h lists its keys) into a SweepDefinition:
// the design, the base scenario and [fixed], the axes, and the check that the base and every
// point make a valid scenario with the same metrics, all before anything runs.
#include "sim/sweep/sweep.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <cstdio>
#include <cstdlib>
#include <set>

#include "base/config_reader.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/core/metrics.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"
#include "sim/sweep/sweep_axis_file.h"

namespace pamsim {
namespace {

using detail::axis_value;
using detail::Where;

// A grid level to 12 significant digits, so a log range lists 0.001, not 0.0010000000000000002.
double tidy(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.12g", v);
  return std::strtod(buf, nullptr);
}

// An axis given as a list of values (grid designs only).
void read_axis_values(const toml::table& t, SweepDesign design, const Where& where,
                      SweepAxis* axis) {
  where.check(design == SweepDesign::kGrid, "values",
              "is for grid designs; random and lhs sample a range (from, to)");
  const toml::array* list = t["values"].as_array();
  where.check(list != nullptr, "values", "must be a list");
  where.check(!list->empty(), "values", "is empty");
  for (const toml::node& n : *list) axis->values.push_back(axis_value(n, where, "values"));
  where.check(!t.contains("count") && !t.contains("scale"), "count",
              "and scale go with from/to, not with values");
}

// A grid axis's `count` levels over its range, ends exact.
void read_grid_levels(const toml::table& t, std::int64_t max_trials, const Where& where,
                      SweepAxis* axis_out) {
  SweepAxis& axis = *axis_out;
  const toml::node* count_node = t.get("count");
  where.check(count_node && count_node->is_integer(), "count", "is required (an integer >= 1)");
  const std::int64_t count = *count_node->value<std::int64_t>();  // >= 1, by its row
  where.check(count > 1 || axis.from == axis.to, "count", "must be >= 2 for a range from != to");
  where.check(count <= max_trials, "count",
              "is " + std::to_string(count) + ", more than max_trials = " +
                  std::to_string(max_trials) + " (raise max_trials to run it)");
  for (std::int64_t i = 0; i < count; ++i) {
    AxisValue v;
    v.number = i == 0           ? axis.from
               : i == count - 1 ? axis.to
                                : tidy(axis.at(static_cast<double>(i) / (count - 1)));
    axis.values.push_back(v);
  }
}

}  // namespace

const std::vector<EntryKey>& axis_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"key", "", "a scenario key, not seed", "(required)", "the scenario key the axis varies",
       EntryType::kText},
      {"values", "(the key's)", "a list (grid designs)", "(values or from/to)",
       "the values, in the key's own unit or type"},
      {"from", "(the key's)", "> 0 on a log scale", "(values or from/to)", "a range's first value",
       EntryType::kNumber},
      {"to", "(the key's)", "", "(values or from/to)", "a range's last value", EntryType::kNumber},
      {"count",
       "",
       "grid designs",
       "(required with from/to)",
       "how many values the range takes",
       EntryType::kInteger,
       {1.0, std::numeric_limits<double>::infinity()}},
      {"scale",
       "",
       "",
       "\"linear\"",
       "how a range spaces its values",
       EntryType::kChoice,
       {},
       {"linear", "log"}}};
  return keys;
}

const std::vector<EntryKey>& case_axis_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"name", "", "a plain name, unique among the axes", "(required)",
       "the axis's column in the outputs", EntryType::kText},
      {"case", "", "[[axis.case]] tables", "(required)", "the axis's named cases"}};
  return keys;
}

const std::vector<EntryKey>& case_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"name", "", "a name, unique in its axis", "(required)", "the case's value in its column",
       EntryType::kText},
      {"from", "", "{ file = \"...\", table = \"...\" }, or a list of them", "(none)",
       "the scenario keys of a table of another file, relative to the sweep file"},
      {"set", "", "a table of scenario keys (lists allowed)", "(none)",
       "the scenario keys the case sets, after from's", EntryType::kTable}};
  return keys;
}

namespace {

SweepAxis read_axis(const toml::table& t, std::size_t index, SweepDesign design,
                    std::int64_t max_trials, const std::string& file) {
  if (t.contains("case") || t.contains("name")) {
    return detail::read_case_axis(t, index, design, file);
  }
  const Where where{file, "axis[" + std::to_string(index) + "]."};
  detail::check_entry(t, axis_entry_keys(), where,
                      "is not a sweep axis key (key, values, from, to, count, scale; or name "
                      "and [[axis.case]])");
  SweepAxis axis;
  const auto key = t["key"].value<std::string>();
  where.check(key.has_value() && !key->empty(), "key",
              "is required (a scenario key, e.g. "
              "\"reflex.v_thr_mm_s\")");
  axis.key = *key;
  where.check(axis.key != "seed", "key", "cannot be \"seed\": use the sweep's `seeds`");

  const bool has_values = t.contains("values");
  const bool has_range = t.contains("from") || t.contains("to");
  where.check(has_values != has_range, "values",
              "or from/to: give exactly one (a list of values or a range)");
  if (has_values) {
    read_axis_values(t, design, where, &axis);
    return axis;
  }

  axis.is_range = true;
  where.check(t.contains("from") && t.contains("to"), "from", "and to are both required");
  axis.from = *t["from"].value<double>();  // finite numbers, by their rows (check_entry)
  axis.to = *t["to"].value<double>();
  axis.log_scale = t["scale"].value_or(std::string("linear")) == "log";  // a row's name
  if (axis.log_scale) {
    where.check(axis.from > 0 && axis.to > 0, "from",
                "and to must be > 0 on a log scale, got " + format_value(axis.from) + " and " +
                    format_value(axis.to));
  }
  if (design != SweepDesign::kGrid) {
    where.check(!t.contains("count"), "count", "is for grid designs (random and lhs use samples)");
    return axis;
  }
  read_grid_levels(t, max_trials, where, &axis);
  return axis;
}

// "point 3 (key = value, ...)", with the draws of seed index s when the sweep draws any
std::string describe_trial(const SweepDefinition& def, std::int64_t trial) {
  const std::int64_t point = trial / def.seeds;
  std::string s = "point " + std::to_string(point) + " (";
  for (std::size_t a = 0; a < def.axes.size(); ++a) {
    s += (a ? ", " : "") + def.axes[a].key + " = " + def.value(point, a).toml();
  }
  if (def.randomize.empty()) return s + ")";
  s += "; seed index " + std::to_string(trial % def.seeds) + " draws";
  const std::vector<double> v = def.draws(trial);
  for (std::size_t k = 0; k < v.size(); ++k) {
    s += (k ? ", " : " ") + def.randomize[k].key + " = " + format_shortest(v[k]);
  }
  return s + ")";
}

// The seed indices whose draws are checked before the sweep runs; later ones are checked as
// their trials run (one refused is stored as a failed trial with the reason).
constexpr std::int64_t kCheckedDraws = 100;

const std::string kRaise = " (raise max_trials to run it)";

// design, max_trials, seeds (rows), and for random/lhs samples and design_seed (rows that a
// grid refuses); then what joins them: the trials within max_trials
void read_design(ConfigReader& in, SweepDefinition* def) {
  read_key_rows(in, sweep_design_table(def));
  in.check(def->seeds <= def->max_trials, "seeds",
           "is " + std::to_string(def->seeds) +
               ", more trials than max_trials = " + std::to_string(def->max_trials) + kRaise);
  const KeyTable sampling = sweep_sampling_table(def);
  if (def->design == SweepDesign::kGrid) {
    for (const std::string& key : key_names(sampling)) {
      in.check(!in.has(key), key, "is for random and lhs designs");
    }
    return;
  }
  in.check(in.has("samples"), "samples",
           std::string("is required for a ") + sweep_design_name(def->design) + " design");
  read_key_rows(in, sampling);
  in.check(def->samples <= def->max_trials / def->seeds, "samples",
           std::to_string(def->samples) + " x seeds " + std::to_string(def->seeds) +
               " is more trials than max_trials = " + std::to_string(def->max_trials) + kRaise);
}

// base (its text) and [fixed]
void read_base(ConfigReader& in, SweepDefinition* def) {
  def->base_path = in.require_path("base", "the base scenario file");
  try {
    def->base_text = read_text_file(def->base_path);
  } catch (const InputError& e) {
    throw InputError(def->file + ": base: " + e.what());
  }
  if (const toml::node* fixed = in.raw("fixed")) {
    const toml::table* t = fixed->as_table();
    in.check(t != nullptr, "fixed", "must be a table of scenario keys");
    detail::flatten_keys(*t, "", Where{def->file, "fixed."}, &def->fixed);
  }
}

void read_axes(ConfigReader& in, SweepDefinition* def) {
  const toml::node* axes = in.raw("axis");
  in.check(axes != nullptr, "axis", "is required: at least one [[axis]]");
  const toml::array* list = axes->as_array();
  in.check(list != nullptr && !list->empty(), "axis", "must be one or more [[axis]] tables");
  std::set<std::string> keys;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::table* t = (*list)[i].as_table();
    in.check(t != nullptr, "axis", "must be [[axis]] tables");
    def->axes.push_back(read_axis(*t, i, def->design, def->max_trials, def->file));
    in.check(keys.insert(def->axes.back().key).second, "axis",
             "names " + def->axes.back().key + " twice");
  }
}

// [[randomize]] and randomize_seed; a drawn key may be neither an axis, a case's nor fixed
// (check_axes_disjoint, the one check of what sets each key)
void read_randomize(ConfigReader& in, SweepDefinition* def) {
  read_randomizations(in, &def->randomize, &def->randomize_seed);
  std::vector<std::string> drawn;
  for (const Randomization& r : def->randomize) drawn.push_back(r.key);
  detail::check_axes_disjoint(def->axes, drawn, def->fixed, def->file);
}

// A grid's points x seeds within max_trials, the product checked factor by factor (it could
// wrap to 0 or below).
void check_grid_size(ConfigReader& in, const SweepDefinition& def) {
  if (def.design != SweepDesign::kGrid) return;
  if (grid_points(def.axes, def.max_trials / def.seeds) >= 0) return;
  double product = 1;  // for the message only
  for (const auto& a : def.axes) product *= static_cast<double>(a.values.size());
  in.fail("max_trials", "is " + std::to_string(def.max_trials) + ", fewer than the grid's " +
                            format_value(product) + " points (" + std::to_string(def.axes.size()) +
                            " axes) x " + std::to_string(def.seeds) + " seeds" + kRaise);
}

// The base scenario, then every point, must validate and bind to its model before anything
// runs (a model is loaded again only where a point changes it); every point must summarise
// its trials in the same metrics (the columns).
void check_points(SweepDefinition* def) {
  Scenario bound;
  TrialModel model;
  const auto names_of = [&](const Scenario& sc) {
    if (&sc == &bound || !same_trial_model(sc, bound)) {
      model = load_trial_model(sc);
      bound = sc;
    }
    std::vector<std::string> labels;
    for (const BoundMuscle& m : model.muscles) labels.push_back(m.label);
    return metric_names(sc, labels, model.joint.hinge, model.model.get());
  };
  try {
    bound = load_scenario_text(def->base_text, def->base_path, def->fixed);
    def->metric_names = names_of(bound);
  } catch (const InputError& e) {
    throw InputError(def->file + ": base scenario: " + e.what());
  }
  const auto& names = def->metric_names;
  for (std::size_t a = 0; a < def->axes.size(); ++a) {
    const std::string& key = def->axes[a].key;
    if (def->axes[a].is_cases() && std::find(names.begin(), names.end(), key) != names.end()) {
      throw InputError(def->file + ": axis[" + std::to_string(a) + "].name " + key +
                       " is a metric's column");
    }
  }
  def->base_seed = bound.seed;
  // every point with the draws of seed index 0, then point 0 with the others' draws
  std::vector<std::int64_t> trials;
  for (std::int64_t p = 0; p < def->points(); ++p) trials.push_back(p * def->seeds);
  const std::int64_t draws = def->randomize.empty() ? 1 : std::min(def->seeds, kCheckedDraws);
  for (std::int64_t s = 1; s < draws; ++s) trials.push_back(s);
  for (std::int64_t t : trials) {
    try {
      const Scenario point =
          load_scenario_text(def->base_text, def->base_path, def->trial_overrides(t));
      if (names_of(point) != def->metric_names) {
        throw InputError(
            "changes the metrics or the muscles' labels, which a sweep's columns "
            "cannot follow");
      }
    } catch (const InputError& e) {
      throw InputError(def->file + ": " + describe_trial(*def, t) + ": " + e.what());
    }
  }
}

}  // namespace

KeyTable sweep_design_table(SweepDefinition* def) {
  KeyTable t{"", {}, {}, {}};
  t.choices = {{"design",
                {"grid", "random", "lhs"},
                "how the axes become points: their full grid, uniform random draws, or a Latin "
                "hypercube",
                [def](const std::string& v) { def->design = parse_sweep_design(v, "design"); },
                [def] { return std::string(sweep_design_name(def->design)); }}};
  t.ints = {int_row("seeds", "seeds per point (common to every point)", 1, kMaxCount, &def->seeds),
            int_row("max_trials",
                    "the most trials (points x seeds) the sweep may hold: a cap against a typo "
                    "that asks for 10^20 trials; raise it for a big sweep",
                    1, kMaxCount, &def->max_trials)};
  return t;
}

KeyTable sweep_sampling_table(SweepDefinition* def) {
  KeyTable t{"", {}, {}, {}};
  t.ints = {int_row("samples", "points of a random or lhs design (required there)", 1, kMaxCount,
                    &def->samples),
            int_row("design_seed", "seed of the random or lhs design's draws", 0,
                    std::int64_t{1} << 62, &def->design_seed)};
  return t;
}

SweepDefinition load_sweep(const std::string& path) {
  ConfigReader in(path);
  SweepDefinition def;
  def.file = path;
  read_design(in, &def);
  read_base(in, &def);
  read_axes(in, &def);
  read_randomize(in, &def);
  in.reject_unknown();
  check_grid_size(in, def);
  make_points(&def);
  check_points(&def);
  return def;
}

}  // namespace pamsim
