// tuning_file.cc: see tuning_file.h.
#include "sim/optimize/tuning_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <nlohmann/json.hpp>

#include "base/config_reader.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/core/metrics.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

// The metric names the base scenario's trials report.
std::vector<std::string> base_metric_names(const Scenario& sc) {
  const TrialModel model = load_trial_model(sc);
  std::vector<std::string> labels;
  for (const BoundMuscle& m : model.muscles) labels.push_back(m.label);
  return metric_names(sc, labels, model.joint.hinge, model.model.get());
}

void read_base(ConfigReader& in, TuneDefinition* def) {
  SearchBase base = read_search_base(in);
  def->base_path = std::move(base.path);
  def->base_text = std::move(base.text);
  def->overrides = std::move(base.overrides);
}

// The rows (tune_search_table), then what joins keys: nsga2's population a multiple of 4 of
// at least 8, the noise levels each once.
void read_search_and_trials(ConfigReader& in, TuneDefinition* def) {
  read_key_rows(in, tune_search_table(def));
  if (def->algorithm == TuneAlgorithm::kNsga2) {
    in.check(
        def->population >= 8 && def->population % 4 == 0, "population",
        "must be a multiple of 4 in [8, 10000] for nsga2, got " + std::to_string(def->population));
  }
  def->noise_scales = in.get_double_list("noise_scales", def->noise_scales);
  in.check(!def->noise_scales.empty(), "noise_scales", "must hold at least one level");
  const std::vector<double>& levels = def->noise_scales;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const double n = levels[i];
    in.check(n >= 0.0 && n <= 1000.0, "noise_scales",
             "must be within [0, 1000], got " + format_value(n));
    in.check(std::find(levels.begin(), levels.begin() + i, n) == levels.begin() + i, "noise_scales",
             "names " + format_value(n) + " twice");
  }
}

// Refuses a metric the base scenario does not report.
void check_metric(ConfigReader& in, const std::vector<std::string>& metrics,
                  const std::string& where, const std::string& m) {
  if (std::find(metrics.begin(), metrics.end(), m) != metrics.end()) return;
  std::string list;
  for (const auto& n : metrics) list += (list.empty() ? "" : ", ") + n;
  in.fail(where, "names no metric of the base scenario: \"" + m + "\" (it has " + list + ")");
}

void read_objectives(ConfigReader& in, const std::vector<std::string>& metrics,
                     TuneDefinition* def) {
  for (const TableEntry& e : TableArray(in, "objective").entries(objective_entry_keys())) {
    TuneObjective o;
    o.metric = e.text("metric", true);
    check_metric(in, metrics, e.where + "metric", o.metric);
    o.maximize = e.table["maximize"].value_or(false);  // true or false, by its row
    def->objectives.push_back(o);
  }
  in.check(!def->objectives.empty(), "objective", "needs at least one [[objective]]");
  in.check(
      def->algorithm == TuneAlgorithm::kNsga2 || def->objectives.size() == 1, "algorithm",
      "cmaes minimises one objective; use \"nsga2\" for " + std::to_string(def->objectives.size()));
}

void read_constraints(ConfigReader& in, const std::vector<std::string>& metrics,
                      TuneDefinition* def) {
  for (const TableEntry& e : TableArray(in, "constraint").entries(constraint_entry_keys())) {
    TuneConstraint c;
    c.metric = e.text("metric", true);
    check_metric(in, metrics, e.where + "metric", c.metric);
    if (const auto v = e.number("min")) c.min = *v;
    if (const auto v = e.number("max")) c.max = *v;
    in.check(std::isfinite(c.min) || std::isfinite(c.max), e.where + "min", "or max is required");
    in.check(c.min <= c.max, e.where + "min", "must not exceed max");
    def->constraints.push_back(c);
  }
}

void read_references(ConfigReader& in, TuneDefinition* def) {
  for (const TableEntry& e : TableArray(in, "reference").entries(reference_entry_keys())) {
    TuneReference r;
    r.name = e.text("name", true);
    const toml::array* values = e.table.get("values") ? e.table.get("values")->as_array() : nullptr;
    if (!values || values->size() != def->parameters.size()) {
      in.fail(e.where + "values", "must be a list of " + std::to_string(def->parameters.size()) +
                                      " numbers, one per [[parameter]]");
    }
    for (const toml::node& n : *values) {
      // (an integer beyond 2^53 has no exact double: toml++ gives none)
      const bool numeric = n.is_integer() || n.is_floating_point();
      const std::optional<double> value = numeric ? n.value<double>() : std::nullopt;
      if (!value) in.fail(e.where + "values", "must be numbers");
      const double v = *value;
      in.check(std::isfinite(v), e.where + "values", "must be finite, got " + format_value(v));
      r.values.push_back(v);
    }
    def->references.push_back(r);
  }
}

// `values` must make a valid scenario; else "<path>: <what> (<name>): <the scenario's error>".
void check_setting(const TuneDefinition& def, const std::vector<double>& values,
                   const std::string& what, const std::string& name) {
  try {
    load_scenario_text(def.base_text, def.base_path, def.overrides_at(values));
  } catch (const InputError& e) {
    throw InputError(def.file + ": " + what + " (" + name + "): " + e.what());
  }
}

// With [[randomize]], the middle of the box on each drawn arm, tuning and held out.
void check_draws(const TuneDefinition& def) {
  if (def.randomize.empty()) return;
  std::vector<double> middle;
  for (const TuneParameter& p : def.parameters) middle.push_back(value_at(p, 0.5));
  std::vector<std::int64_t> indices;
  for (int s = 0; s < def.seeds; ++s) indices.push_back(s);
  for (int s = 0; s < def.held_out_seeds; ++s) {
    indices.push_back(static_cast<std::int64_t>(kHeldOutSeedOffset) + s);
  }
  for (std::int64_t s : indices) {
    std::vector<std::string> o = def.overrides_at(middle);
    append_draws(def.randomize, def.randomize_seed, s, &o);
    try {
      load_scenario_text(def.base_text, def.base_path, o);
    } catch (const InputError& e) {
      throw InputError(def.file + ": randomize (the draws of seed index " + std::to_string(s) +
                       "): " + e.what());
    }
  }
}

// Every reference, and every parameter at both bounds (the others mid-range), must make a
// valid scenario (a bad key fails here).
void check_settings(const TuneDefinition& def) {
  check_draws(def);
  for (std::size_t i = 0; i < def.references.size(); ++i) {
    check_setting(def, def.references[i].values, "reference[" + std::to_string(i) + "]",
                  def.references[i].name);
  }
  for (std::size_t i = 0; i < def.parameters.size(); ++i) {
    for (double u : {0.0, 1.0}) {
      std::vector<double> values;
      for (const TuneParameter& p : def.parameters) values.push_back(value_at(p, 0.5));
      values[i] = value_at(def.parameters[i], u);
      check_setting(def, values, "parameter[" + std::to_string(i) + "]", def.parameters[i].key);
    }
  }
}

}  // namespace

const std::vector<EntryKey>& objective_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"metric", "", "a summary metric of the base scenario", "(required)",
       "the metric the search minimises (its mean over the seeds)", EntryType::kText},
      {"maximize", "", "", "false", "maximise the metric instead", EntryType::kBool}};
  return keys;
}

const std::vector<EntryKey>& constraint_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"metric", "", "a summary metric of the base scenario", "(required)",
       "the metric a point must keep within [min, max] (its mean over the seeds)",
       EntryType::kText},
      {"min", "(the metric's)", "at most max", "(none)", "its lowest allowed mean",
       EntryType::kNumber},
      {"max", "(the metric's)", "", "(none)", "its highest allowed mean; min or max",
       EntryType::kNumber}};
  return keys;
}

const std::vector<EntryKey>& reference_entry_keys() {
  static const std::vector<EntryKey> keys = {
      {"name", "", "", "(required)", "a setting evaluated beside the search's best",
       EntryType::kText},
      {"values", "(the parameters')", "one number per [[parameter]], in their order", "(required)",
       "the setting's parameter values"}};
  return keys;
}

KeyTable tune_search_table(TuneDefinition* def) {
  KeyTable t{"", {}, {}, {}};
  t.choices = {
      {"algorithm",
       {"cmaes", "nsga2"},
       "pagmo2's CMA-ES (exactly one objective) or NSGA-II (one or more)",
       [def](const std::string& v) {
         def->algorithm = v == "cmaes" ? TuneAlgorithm::kCmaes : TuneAlgorithm::kNsga2;
       },
       [def] { return std::string(def->algorithm == TuneAlgorithm::kCmaes ? "cmaes" : "nsga2"); }}};
  t.ints = {int_row("generations", "the optimiser's generations", 1, 10000, &def->generations),
            int_row("population", "its population (nsga2: a multiple of 4, at least 8)", 5, 10000,
                    &def->population),
            int_row("seed", "the optimiser's seed (pagmo's seeds are 32-bit)", 0, 4294967295LL,
                    &def->seed),
            int_row("seeds", "trials per noise level of an evaluation (seeds base.seed ..)", 1,
                    1000, &def->seeds),
            int_row("held_out_seeds", "seeds of the final check (base.seed + 1000 ..)", 0, 1000,
                    &def->held_out_seeds)};
  return t;
}

TuneDefinition load_tune_definition(const std::string& path) {
  ConfigReader in(path);
  TuneDefinition def;
  def.file = path;
  read_base(in, &def);
  read_search_and_trials(in, &def);
  // the base scenario must load with the overrides, and tells which metrics exist
  Scenario base;
  try {
    base = load_scenario_text(def.base_text, def.base_path, def.overrides);
  } catch (const InputError& e) {
    in.fail("base", std::string("(") + e.what() + ")");
  }
  const std::vector<std::string> metrics = base_metric_names(base);
  def.parameters = read_search_parameters(in, {"seed", "sensors.noise_scale"},
                                          "use the tuning file's seeds / noise_scales");
  read_objectives(in, metrics, &def);
  read_constraints(in, metrics, &def);
  read_references(in, &def);
  read_randomizations(in, &def.randomize, &def.randomize_seed);
  for (const Randomization& r : def.randomize) {
    in.check(r.key != "sensors.noise_scale", "randomize",
             "cannot draw sensors.noise_scale: "
             "use the tuning file's noise_scales");
    for (const TuneParameter& p : def.parameters) {
      in.check(p.key != r.key, "randomize", "draws " + r.key + ", which is a parameter too");
    }
  }
  in.reject_unknown();
  check_settings(def);
  return def;
}

std::string TuneDefinition::canonical_json() const {
  const nlohmann::json params = search_parameters_json(parameters);
  nlohmann::json objs = nlohmann::json::array();
  for (const auto& o : objectives) objs.push_back({{"metric", o.metric}, {"maximize", o.maximize}});
  nlohmann::json cons = nlohmann::json::array();
  for (const auto& c : constraints) {
    nlohmann::json j = {{"metric", c.metric}};
    if (std::isfinite(c.min)) j["min"] = c.min;
    if (std::isfinite(c.max)) j["max"] = c.max;
    cons.push_back(j);
  }
  nlohmann::json refs = nlohmann::json::array();
  for (const auto& r : references) refs.push_back({{"name", r.name}, {"values", r.values}});
  nlohmann::json j = {{"base_scenario", base_text},
                      {"base_path", base_path},
                      {"overrides", overrides},
                      {"algorithm", algorithm == TuneAlgorithm::kCmaes ? "cmaes" : "nsga2"},
                      {"generations", generations},
                      {"population", population},
                      {"seed", seed},
                      {"seeds", seeds},
                      {"noise_scales", noise_scales},
                      {"held_out_seeds", held_out_seeds},
                      {"parameters", params},
                      {"objectives", objs},
                      {"constraints", cons},
                      {"references", refs}};
  if (!randomize.empty()) {  // (a definition without draws reads as before they existed)
    j["randomize"] = randomizations_json(randomize);
    j["randomize_seed"] = randomize_seed;
  }
  return j.dump();
}

namespace {

// The lists of a canonical definition (throws nlohmann::json::exception on a missing field).
void lists_from_json(const nlohmann::json& j, TuneDefinition* def) {
  for (const auto& p : j.at("parameters")) {
    def->parameters.push_back({p.at("key"), p.at("from"), p.at("to"), p.at("log")});
  }
  for (const auto& o : j.at("objectives"))
    def->objectives.push_back({o.at("metric"), o.at("maximize")});
  for (const auto& c : j.at("constraints")) {
    TuneConstraint k;
    k.metric = c.at("metric");
    if (c.contains("min")) k.min = c.at("min");
    if (c.contains("max")) k.max = c.at("max");
    def->constraints.push_back(k);
  }
  for (const auto& r : j.at("references")) {
    def->references.push_back({r.at("name"), r.at("values").get<std::vector<double>>()});
  }
}

}  // namespace

TuneDefinition tune_definition_from_json(const std::string& json, const std::string& file,
                                         const std::string& where) {
  const auto j = nlohmann::json::parse(json, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    throw InputError(where + ": its tuning definition cannot be read");
  }
  try {
    TuneDefinition def;
    def.file = file;
    def.base_text = j.at("base_scenario").get<std::string>();
    def.base_path = j.at("base_path").get<std::string>();
    def.overrides = j.at("overrides").get<std::vector<std::string>>();
    def.algorithm = j.at("algorithm") == "cmaes" ? TuneAlgorithm::kCmaes : TuneAlgorithm::kNsga2;
    def.generations = j.at("generations").get<unsigned>();
    def.population = j.at("population").get<unsigned>();
    def.seed = j.at("seed").get<std::uint64_t>();
    def.seeds = j.at("seeds").get<int>();
    def.noise_scales = j.at("noise_scales").get<std::vector<double>>();
    def.held_out_seeds = j.at("held_out_seeds").get<int>();
    lists_from_json(j, &def);
    if (j.contains("randomize")) {
      def.randomize = randomizations_from_json(j.at("randomize"));
      def.randomize_seed = j.at("randomize_seed").get<std::uint64_t>();
    }
    return def;
  } catch (const nlohmann::json::exception& e) {
    // a damaged database, or one from a pamsim whose definition had other fields
    throw InputError(where + ": its tuning definition cannot be read (" + e.what() + ")");
  }
}

}  // namespace pamsim
