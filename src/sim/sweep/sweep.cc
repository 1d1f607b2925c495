// sweep.cc: see sweep.h.
#include "sim/sweep/sweep.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/config_reader.h"
#include "sim/core/metrics.h"
#include "sim/core/trial_model.h"
#include "sim/io/scenario_file.h"

namespace pamsim {
namespace {

// Where a problem is: "<file>: axis[<i>].<key>" and the like.
struct Where {
  const std::string& file;
  std::string prefix;
  [[noreturn]] void fail(const std::string& key, const std::string& problem) const {
    throw InputError(file + ": " + prefix + key + " " + problem);
  }
  void check(bool ok, const std::string& key, const std::string& problem) const {
    if (!ok) fail(key, problem);
  }
};

AxisValue axis_value(const toml::node& n, const Where& where, const std::string& key) {
  AxisValue v;
  if (n.is_integer()) {
    v.kind = AxisValue::Kind::kInteger;
    v.number = static_cast<double>(*n.value<std::int64_t>());
  } else if (n.is_floating_point()) {
    v.number = *n.value<double>();
    where.check(std::isfinite(v.number), key, "must be finite, got " + format_value(v.number));
  } else if (n.is_string()) {
    v.kind = AxisValue::Kind::kString;
    v.text = *n.value<std::string>();
  } else if (n.is_boolean()) {
    v.kind = AxisValue::Kind::kBool;
    v.flag = *n.value<bool>();
  } else {
    where.fail(key, "must be a number, a string or a boolean");
  }
  return v;
}

double number_of(const toml::table& t, const char* key, const Where& where) {
  const toml::node* n = t.get(key);
  if (!n || !(n->is_integer() || n->is_floating_point())) where.fail(key, "must be a number");
  const double v = *n->value<double>();
  where.check(std::isfinite(v), key, "must be finite, got " + format_value(v));
  return v;
}

// The value at fraction u in [0, 1] of the axis's range.
double in_range(const SweepAxis& axis, double u) {
  if (axis.log_scale) {
    return std::exp(std::log(axis.from) + u * (std::log(axis.to) - std::log(axis.from)));
  }
  return axis.from + u * (axis.to - axis.from);
}

// A grid level to 12 significant digits, so a log range lists 0.001, not 0.0010000000000000002.
double tidy(double v) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.12g", v);
  return std::strtod(buf, nullptr);
}

SweepAxis read_axis(const toml::table& t, std::size_t index, SweepDesign design,
                    std::int64_t max_trials, const std::string& file) {
  const Where where{file, "axis[" + std::to_string(index) + "]."};
  static const std::set<std::string> known = {"key", "values", "from", "to", "count", "scale"};
  for (const auto& [k, _] : t) {
    if (!known.count(std::string(k.str()))) {
      where.fail(std::string(k.str()), "is not a sweep axis key (key, values, from, to, count, scale)");
    }
  }
  SweepAxis axis;
  const auto key = t["key"].value<std::string>();
  where.check(key.has_value() && !key->empty(), "key", "is required (a scenario key, e.g. "
              "\"reflex.v_thr_mm_s\")");
  axis.key = *key;
  where.check(axis.key != "seed", "key", "cannot be \"seed\": use the sweep's `seeds`");

  const bool has_values = t.contains("values");
  const bool has_range = t.contains("from") || t.contains("to");
  where.check(has_values != has_range, "values",
              "or from/to: give exactly one (a list of values or a range)");
  if (has_values) {
    where.check(design == SweepDesign::kGrid, "values",
                "is for grid designs; random and lhs sample a range (from, to)");
    const toml::array* list = t["values"].as_array();
    where.check(list != nullptr, "values", "must be a list");
    where.check(!list->empty(), "values", "is empty");
    for (const toml::node& n : *list) axis.values.push_back(axis_value(n, where, "values"));
    where.check(!t.contains("count") && !t.contains("scale"), "count",
                "and scale go with from/to, not with values");
    return axis;
  }

  axis.is_range = true;
  where.check(t.contains("from") && t.contains("to"), "from", "and to are both required");
  axis.from = number_of(t, "from", where);
  axis.to = number_of(t, "to", where);
  const std::string scale = t["scale"].value_or(std::string("linear"));
  where.check(scale == "linear" || scale == "log", "scale",
              "must be \"linear\" or \"log\", got \"" + scale + "\"");
  axis.log_scale = scale == "log";
  if (axis.log_scale) {
    where.check(axis.from > 0 && axis.to > 0, "from",
                "and to must be > 0 on a log scale, got " + format_value(axis.from) + " and " +
                    format_value(axis.to));
  }
  if (design != SweepDesign::kGrid) {
    where.check(!t.contains("count"), "count", "is for grid designs (random and lhs use samples)");
    return axis;
  }
  const toml::node* count_node = t.get("count");
  where.check(count_node && count_node->is_integer(), "count", "is required (an integer >= 1)");
  const std::int64_t count = *count_node->value<std::int64_t>();
  where.check(count >= 1, "count", "must be >= 1, got " + std::to_string(count));
  where.check(count > 1 || axis.from == axis.to, "count", "must be >= 2 for a range from != to");
  where.check(count <= max_trials, "count",
              "is " + std::to_string(count) + ", more than max_trials = " +
                  std::to_string(max_trials) + " (raise max_trials to run it)");
  for (std::int64_t i = 0; i < count; ++i) {
    AxisValue v;
    v.number = i == 0 ? axis.from
             : i == count - 1 ? axis.to
                              : tidy(in_range(axis, static_cast<double>(i) / (count - 1)));
    axis.values.push_back(v);
  }
  return axis;
}

// "a.b=value" for every leaf of [fixed].
void flatten_fixed(const toml::table& t, const std::string& prefix, const std::string& file,
                   std::vector<std::string>* out) {
  const Where where{file, "fixed."};
  for (const auto& [k, node] : t) {
    const std::string key = prefix + std::string(k.str());
    if (const toml::table* sub = node.as_table()) {
      flatten_fixed(*sub, key + ".", file, out);
    } else {
      out->push_back(key + "=" + axis_value(node, where, key).toml());
    }
  }
}

// A uniform double in [0, 1) from the top 53 bits (the same on every platform).
double unit_uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// The number of points of a grid (the product of the axes' levels), or -1 once it exceeds
// `cap` (the product is never formed past it, so it cannot wrap).
std::int64_t grid_points(const std::vector<SweepAxis>& axes, std::int64_t cap) {
  std::int64_t n = 1;
  for (const auto& a : axes) {
    const auto levels = static_cast<std::int64_t>(a.values.size());
    if (levels > cap / n) return -1;
    n *= levels;
  }
  return n;
}

void make_points(SweepDefinition* def) {
  const std::size_t n_axes = def->axes.size();
  std::vector<AxisValue>& out = def->point_values;
  if (def->design == SweepDesign::kGrid) {
    const std::int64_t n = grid_points(def->axes, std::numeric_limits<std::int64_t>::max());
    out.resize(static_cast<std::size_t>(n) * n_axes);
    for (std::int64_t p = 0; p < n; ++p) {   // row-major: the first axis varies slowest
      std::int64_t rest = p;
      for (std::size_t a = n_axes; a-- > 0;) {
        const auto levels = static_cast<std::int64_t>(def->axes[a].values.size());
        out[p * n_axes + a] = def->axes[a].values[rest % levels];
        rest /= levels;
      }
    }
    return;
  }
  const std::int64_t n = def->samples;
  out.resize(static_cast<std::size_t>(n) * n_axes);
  std::mt19937_64 rng(def->design_seed);
  for (std::size_t a = 0; a < n_axes; ++a) {
    // Latin hypercube: each of the n strata of every axis holds exactly one point
    std::vector<std::int64_t> stratum(n);
    for (std::int64_t i = 0; i < n; ++i) stratum[i] = i;
    if (def->design == SweepDesign::kLatinHypercube) {
      for (std::int64_t i = n - 1; i > 0; --i) {   // Fisher-Yates with a portable draw
        std::swap(stratum[i], stratum[rng() % static_cast<std::uint64_t>(i + 1)]);
      }
    }
    for (std::int64_t p = 0; p < n; ++p) {
      const double u = def->design == SweepDesign::kLatinHypercube
                           ? (stratum[p] + unit_uniform(rng)) / static_cast<double>(n)
                           : unit_uniform(rng);
      out[p * n_axes + a].number = in_range(def->axes[a], u);
    }
  }
}

std::string describe_point(const SweepDefinition& def, std::int64_t point) {
  std::string s;
  for (std::size_t a = 0; a < def.axes.size(); ++a) {
    s += (a ? ", " : "") + def.axes[a].key + " = " + def.value(point, a).toml();
  }
  return s;
}

}  // namespace

const char* sweep_design_name(SweepDesign design) {
  switch (design) {
    case SweepDesign::kGrid: return "grid";
    case SweepDesign::kRandom: return "random";
    case SweepDesign::kLatinHypercube: return "lhs";
  }
  return "?";
}

std::string AxisValue::toml() const {
  switch (kind) {
    case Kind::kString: {
      std::ostringstream os;
      os << toml::value<std::string>(text);   // quoted and escaped as TOML
      return os.str();
    }
    case Kind::kBool: return flag ? "true" : "false";
    case Kind::kInteger: return std::to_string(static_cast<std::int64_t>(number));
    case Kind::kNumber: break;
  }
  if (!std::isfinite(number)) return std::isnan(number) ? "nan" : number > 0 ? "inf" : "-inf";
  char buf[40];
  const auto end = std::to_chars(buf, buf + sizeof(buf), number).ptr;   // shortest exact form
  std::string s(buf, end);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";   // stay a float in TOML
  return s;
}

std::string SweepShard::text() const {
  return std::to_string(index) + "/" + std::to_string(count);
}

SweepShard parse_sweep_shard(const std::string& text, const std::string& source) {
  const auto bad = [&] {
    return InputError(source + " must be I/N with 0 <= I < N, got '" + text + "'");
  };
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) throw bad();
  // a decimal integer that fills its part of the text, or -1
  const auto number = [](const std::string& part) -> std::int64_t {
    std::int64_t value = -1;
    const char* end = part.data() + part.size();
    const auto [ptr, ec] = std::from_chars(part.data(), end, value);
    return part.empty() || ec != std::errc() || ptr != end ? -1 : value;
  };
  SweepShard shard;
  shard.index = number(text.substr(0, slash));
  shard.count = number(text.substr(slash + 1));
  if (shard.index < 0 || shard.count < 1 || shard.index >= shard.count) throw bad();
  return shard;
}

std::int64_t SweepDefinition::points() const {
  return axes.empty() ? 0 : static_cast<std::int64_t>(point_values.size() / axes.size());
}

const AxisValue& SweepDefinition::value(std::int64_t point, std::size_t axis) const {
  return point_values[static_cast<std::size_t>(point) * axes.size() + axis];
}

std::vector<std::string> SweepDefinition::overrides(std::int64_t point) const {
  std::vector<std::string> out = fixed;
  for (std::size_t a = 0; a < axes.size(); ++a) out.push_back(axes[a].key + "=" + value(point, a).toml());
  return out;
}

std::uint64_t SweepDefinition::seed_of(std::int64_t trial) const {
  return base_seed + static_cast<std::uint64_t>(trial % seeds);
}

std::string SweepDefinition::canonical_json() const {
  nlohmann::json axes_json = nlohmann::json::array();
  for (const auto& a : axes) {
    nlohmann::json j = {{"key", a.key}};
    if (a.is_range) j["range"] = {{"from", a.from}, {"to", a.to}, {"log", a.log_scale}};
    nlohmann::json values = nlohmann::json::array();
    for (const auto& v : a.values) values.push_back(v.toml());
    j["values"] = values;
    axes_json.push_back(j);
  }
  const nlohmann::json j = {{"base_scenario", base_text}, {"fixed", fixed},
                            {"axes", axes_json},          {"design", sweep_design_name(design)},
                            {"samples", samples},         {"design_seed", design_seed},
                            {"seeds", seeds},             {"metrics", metric_names}};
  return j.dump();
}

SweepDefinition load_sweep(const std::string& path) {
  ConfigReader in(path);
  SweepDefinition def;
  def.file = path;

  const std::string design = in.get_string("design", "grid");
  if (design == "grid") def.design = SweepDesign::kGrid;
  else if (design == "random") def.design = SweepDesign::kRandom;
  else if (design == "lhs") def.design = SweepDesign::kLatinHypercube;
  else in.fail("design", "must be \"grid\", \"random\" or \"lhs\", got \"" + design + "\"");

  def.max_trials = in.get_int("max_trials", def.max_trials);
  in.check(def.max_trials >= 1, "max_trials",
           "must be >= 1, got " + std::to_string(def.max_trials));
  const std::string raise = " (raise max_trials to run it)";
  def.seeds = in.get_int("seeds", 1);
  in.check(def.seeds >= 1, "seeds", "must be >= 1, got " + std::to_string(def.seeds));
  in.check(def.seeds <= def.max_trials, "seeds",
           "is " + std::to_string(def.seeds) + ", more trials than max_trials = " +
               std::to_string(def.max_trials) + raise);
  if (def.design == SweepDesign::kGrid) {
    in.check(!in.has("samples"), "samples", "is for random and lhs designs");
    in.check(!in.has("design_seed"), "design_seed", "is for random and lhs designs");
  } else {
    def.samples = in.get_int("samples", 0);
    in.check(def.samples >= 1, "samples", "must be >= 1 for a " + design + " design, got " +
                                              std::to_string(def.samples));
    in.check(def.samples <= def.max_trials / def.seeds, "samples",
             std::to_string(def.samples) + " x seeds " + std::to_string(def.seeds) +
                 " is more trials than max_trials = " + std::to_string(def.max_trials) + raise);
    const std::int64_t seed = in.get_int("design_seed", 1);
    in.check(seed >= 0, "design_seed", "must be >= 0, got " + std::to_string(seed));
    def.design_seed = static_cast<std::uint64_t>(seed);
  }

  def.base_path = in.get_path("base", "");
  in.check(!def.base_path.empty(), "base", "is required (the base scenario file)");
  try {
    def.base_text = read_text_file(def.base_path);
  } catch (const InputError& e) {
    throw InputError(path + ": base: " + e.what());
  }

  if (const toml::node* fixed = in.raw("fixed")) {
    const toml::table* t = fixed->as_table();
    in.check(t != nullptr, "fixed", "must be a table of scenario keys");
    flatten_fixed(*t, "", path, &def.fixed);
  }

  const toml::node* axes = in.raw("axis");
  in.check(axes != nullptr, "axis", "is required: at least one [[axis]]");
  const toml::array* list = axes->as_array();
  in.check(list != nullptr && !list->empty(), "axis", "must be one or more [[axis]] tables");
  std::set<std::string> keys;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::table* t = (*list)[i].as_table();
    in.check(t != nullptr, "axis", "must be [[axis]] tables");
    def.axes.push_back(read_axis(*t, i, def.design, def.max_trials, path));
    in.check(keys.insert(def.axes.back().key).second, "axis",
             "names " + def.axes.back().key + " twice");
  }
  in.reject_unknown();
  if (def.design == SweepDesign::kGrid) {
    // the product of the levels, checked factor by factor (it could wrap to 0 or below)
    const std::int64_t points = grid_points(def.axes, def.max_trials / def.seeds);
    if (points < 0) {
      double product = 1;   // for the message only
      for (const auto& a : def.axes) product *= static_cast<double>(a.values.size());
      in.fail("max_trials", "is " + std::to_string(def.max_trials) + ", fewer than the grid's " +
                                format_value(product) + " points (" +
                                std::to_string(def.axes.size()) + " axes) x " +
                                std::to_string(def.seeds) + " seeds" + raise);
    }
  }
  make_points(&def);

  // the base scenario, then every point, must validate and bind to its model before anything
  // runs (a model is loaded again only where a point changes it); every point must
  // summarise its trials in the same metrics (the columns)
  Scenario bound;
  TrialModel model;
  const auto names_of = [&](const Scenario& sc) {
    if (&sc == &bound || !same_trial_model(sc, bound)) {
      model = load_trial_model(sc);
      bound = sc;
    }
    std::vector<std::string> labels;
    for (const BoundMuscle& m : model.muscles) labels.push_back(m.label);
    return metric_names(sc, labels, model.joint.hinge);
  };
  try {
    bound = load_scenario_text(def.base_text, def.base_path, def.fixed);
    def.metric_names = names_of(bound);
  } catch (const InputError& e) {
    throw InputError(path + ": base scenario: " + e.what());
  }
  def.base_seed = bound.seed;
  for (std::int64_t p = 0; p < def.points(); ++p) {
    try {
      const Scenario point = load_scenario_text(def.base_text, def.base_path, def.overrides(p));
      if (names_of(point) != def.metric_names) {
        throw InputError("changes the metrics or the muscles' labels, which a sweep's columns "
                         "cannot follow");
      }
    } catch (const InputError& e) {
      throw InputError(path + ": point " + std::to_string(p) + " (" + describe_point(def, p) +
                       "): " + e.what());
    }
  }
  return def;
}

}  // namespace pamsim
