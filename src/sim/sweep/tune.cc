// tune.cc: see tune.h.
#include "sim/sweep/tune.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/types.hpp>
#include <sstream>
#include <stdexcept>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "sim/core/metrics.h"
#include "sim/core/runner.h"
#include "sim/core/trial_model.h"
#include "sim/io/build_info.h"
#include "sim/io/provenance.h"
#include "base/config_reader.h"
#include "sim/io/gnuplot.h"
#include "sim/io/outputs.h"
#include "sim/io/scenario_file.h"
#include "sim/io/staged_outputs.h"
#include "sim/sweep/report.h"
#include "sim/sweep/sqlite_file.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::uint64_t kHeldOutSeedOffset = 1000;

// --- the definition ---------------------------------------------------------------------

const toml::table& table_at(ConfigReader& in, const toml::array& list, std::size_t i,
                            const std::string& name) {
  const toml::table* t = list[i].as_table();
  if (!t) in.fail(name + "[" + std::to_string(i) + "]", "must be a table");
  return *t;
}

// "<name>[i].<key>" checks on one table of an array of tables
struct Entry {
  ConfigReader& in;
  const toml::table& t;
  std::string where;  // "parameter[0]."
  void allow(std::initializer_list<const char*> keys) const {
    for (const auto& [k, v] : t) {
      const std::string key(k.str());
      if (std::none_of(keys.begin(), keys.end(), [&](const char* a) { return key == a; })) {
        in.fail(where + key, "is not a key of this table");
      }
    }
  }
  std::string text(const char* key, bool required, const std::string& fallback = "") const {
    const toml::node* n = t.get(key);
    if (!n) {
      if (required) in.fail(where + key, "is required");
      return fallback;
    }
    if (!n->is_string()) in.fail(where + key, "must be a string");
    return *n->value<std::string>();
  }
  std::optional<double> number(const char* key) const {
    const toml::node* n = t.get(key);
    if (!n) return std::nullopt;
    if (!(n->is_integer() || n->is_floating_point())) in.fail(where + key, "must be a number");
    const double v = *n->value<double>();
    in.check(std::isfinite(v), where + key, "must be finite, got " + format_value(v));
    return v;
  }
};

const toml::array* array_of_tables(ConfigReader& in, const std::string& name) {
  const toml::node* n = in.raw(name);
  if (!n) return nullptr;
  const toml::array* a = n->as_array();
  if (!a) in.fail(name, "must be an array of tables ([[" + name + "]])");
  return a;
}

// The metric names the base scenario's trials report.
std::vector<std::string> base_metric_names(const Scenario& sc) {
  const TrialModel model = load_trial_model(sc);
  std::vector<std::string> labels;
  for (const BoundMuscle& m : model.muscles) labels.push_back(m.label);
  return metric_names(sc, labels, model.joint.hinge);
}

double value_at(const TuneParameter& p, double u) {
  if (p.log) return std::exp(std::log(p.from) + u * (std::log(p.to) - std::log(p.from)));
  return p.from + u * (p.to - p.from);
}

// the scenario overrides that set the parameters
std::vector<std::string> parameter_overrides(const TuneDefinition& def,
                                             const std::vector<double>& values) {
  std::vector<std::string> out = def.overrides;
  for (std::size_t i = 0; i < def.parameters.size(); ++i) {
    out.push_back(def.parameters[i].key + "=" + format_number(values[i]));
  }
  return out;
}

// --- evaluating a setting ----------------------------------------------------------------

struct TrialOutcome {
  std::uint64_t seed = 0;
  double noise_scale = 1.0;
  TrialSummary summary;
};

// Runs a setting's trials (seeds x noise levels) on the pool. Trials whose scenario keeps
// the base's model share it.
std::vector<TrialOutcome> run_setting(const TuneDefinition& def, const std::vector<double>& values,
                                      std::uint64_t first_seed_offset, int seeds, int threads) {
  std::vector<Scenario> scenarios;
  for (double noise : def.noise_scales) {
    std::vector<std::string> o = parameter_overrides(def, values);
    o.push_back("sensors.noise_scale=" + format_number(noise));
    scenarios.push_back(load_scenario_text(def.base_text, def.base_path, o));
  }
  // the noise levels differ only in the sensors: one bound model serves them all (compiling
  // the MJCF again per level would double an evaluation's set-up)
  std::vector<TrialModel> models;
  std::vector<std::size_t> model_of(scenarios.size());
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    std::size_t m = 0;
    while (m < i && !same_trial_model(scenarios[i], scenarios[model_of[m]])) ++m;
    if (m == i) {
      model_of[i] = models.size();
      models.push_back(load_trial_model(scenarios[i]));
    } else {
      model_of[i] = model_of[m];
    }
  }
  const int per_level = seeds;
  std::vector<TrialOutcome> out(def.noise_scales.size() * static_cast<std::size_t>(per_level));
  parallel_for(static_cast<int>(out.size()), threads, [&](int k) {
    const std::size_t level = static_cast<std::size_t>(k / per_level);
    const Scenario& sc = scenarios[level];
    const std::uint64_t seed =
        sc.seed + first_seed_offset + static_cast<std::uint64_t>(k % per_level);
    TrialOutcome& t = out[static_cast<std::size_t>(k)];
    t.seed = seed;
    t.noise_scale = def.noise_scales[level];
    t.summary = run_trial(models[model_of[level]], sc, seed, /*keep_trajectory=*/false).summary;
  });
  return out;
}

// The mean of a metric over the trials that ran to the end (NaN if none).
double mean_metric(const std::vector<TrialOutcome>& trials, const std::string& metric) {
  double sum = 0.0;
  int n = 0;
  for (const TrialOutcome& t : trials) {
    if (t.summary.status != "ok") continue;
    const double v = t.summary.metric(metric);
    if (!std::isfinite(v)) continue;
    sum += v;
    ++n;
  }
  return n ? sum / n : kNaN;
}

TuneEvaluation score(const TuneDefinition& def, const std::vector<double>& values,
                     const std::vector<TrialOutcome>& trials) {
  TuneEvaluation e;
  e.values = values;
  e.trials = static_cast<int>(trials.size());
  for (const TrialOutcome& t : trials) e.ok += t.summary.status == "ok";
  e.violation = static_cast<double>(e.trials - e.ok);
  for (const TuneConstraint& c : def.constraints) {
    const double m = mean_metric(trials, c.metric);
    if (std::isnan(m)) {
      e.violation += 1.0;
      continue;
    }
    e.violation += std::max(0.0, c.min - m) + std::max(0.0, m - c.max);
  }
  for (const TuneObjective& o : def.objectives) {
    const double m = mean_metric(trials, o.metric);
    e.objectives.push_back(m);
    const double signed_m = std::isnan(m) ? 1e6 : (o.maximize ? -m : m);
    e.fitness.push_back(signed_m + kTunePenalty * e.violation);
  }
  return e;
}

// --- the database -------------------------------------------------------------------------

Statement prepare(sqlite3* db, const std::string& sql) {
  Statement s = prepare_statement(db, sql);
  if (!s) throw std::runtime_error(std::string("tune database: ") + sqlite3_errmsg(db));
  return s;
}

sqlite3* open_db(const std::string& path, int flags) {
  sqlite3* db = nullptr;
  const int rc = sqlite3_open_v2(path.c_str(), &db, flags, nullptr);
  if (rc != SQLITE_OK) {
    const std::string why = db ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
    sqlite3_close(db);
    throw InputError(path + ": cannot open the tuning database (" + why + ")");
  }
  sqlite3_busy_timeout(db, 10000);
  return db;
}

int take_lock(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0 || ::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;   // before close() can change it
    if (fd >= 0) ::close(fd);
    throw InputError(path + (error == EWOULDBLOCK ? ": another pamsim tune is writing to it"
                                                  : ": cannot lock the tuning database (" +
                                                        std::string(std::strerror(error)) + ")"));
  }
  return fd;
}

}  // namespace

// --- TuneDefinition -------------------------------------------------------------------------

std::string TuneDefinition::canonical_json() const {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : parameters) {
    params.push_back({{"key", p.key}, {"from", p.from}, {"to", p.to}, {"log", p.log}});
  }
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
  const nlohmann::json j = {{"base_scenario", base_text},
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
  return j.dump();
}

TuneDefinition load_tune_definition(const std::string& path) {
  ConfigReader in(path);
  TuneDefinition def;
  def.file = path;
  def.base_path = in.get_path("base", "");
  in.check(!def.base_path.empty(), "base", "is required (the base scenario file)");
  // absolute: the stored definition must not depend on the folder pamsim ran from
  def.base_path = fs::weakly_canonical(fs::absolute(def.base_path)).string();
  try {
    def.base_text = read_text_file(def.base_path);
  } catch (const InputError& e) {
    in.fail("base", std::string("(") + e.what() + ")");
  }
  def.overrides = in.get_string_list("overrides", {});
  const std::string algorithm = in.get_string("algorithm", "cmaes");
  in.check(algorithm == "cmaes" || algorithm == "nsga2", "algorithm",
           "must be \"cmaes\" or \"nsga2\", got \"" + algorithm + "\"");
  def.algorithm = algorithm == "cmaes" ? TuneAlgorithm::kCmaes : TuneAlgorithm::kNsga2;
  const std::int64_t generations = in.get_int("generations", def.generations);
  in.check(generations >= 1 && generations <= 10000, "generations",
           "must be in [1, 10000], got " + std::to_string(generations));
  def.generations = static_cast<unsigned>(generations);
  const std::int64_t population = in.get_int("population", def.population);
  if (def.algorithm == TuneAlgorithm::kCmaes) {
    in.check(population >= 5 && population <= 10000, "population",
             "must be in [5, 10000] for cmaes, got " + std::to_string(population));
  } else {
    in.check(population >= 8 && population <= 10000 && population % 4 == 0, "population",
             "must be a multiple of 4 in [8, 10000] for nsga2, got " + std::to_string(population));
  }
  def.population = static_cast<unsigned>(population);
  const std::int64_t seed = in.get_int("seed", 1);
  in.check(seed >= 0 && seed <= 4294967295LL, "seed",
           "must be in [0, 2^32 - 1] (pagmo's seeds), got " + std::to_string(seed));
  def.seed = static_cast<std::uint64_t>(seed);
  const std::int64_t seeds = in.get_int("seeds", def.seeds);
  in.check(seeds >= 1 && seeds <= 1000, "seeds",
           "must be in [1, 1000] (an objective needs trials), got " + std::to_string(seeds));
  def.seeds = static_cast<int>(seeds);
  def.noise_scales = in.get_double_list("noise_scales", def.noise_scales);
  in.check(!def.noise_scales.empty(), "noise_scales", "must hold at least one level");
  for (std::size_t i = 0; i < def.noise_scales.size(); ++i) {
    const double n = def.noise_scales[i];
    in.check(n >= 0.0 && n <= 1000.0, "noise_scales",
             "must be within [0, 1000], got " + format_value(n));
    in.check(std::find(def.noise_scales.begin(), def.noise_scales.begin() + i, n) ==
                 def.noise_scales.begin() + i,
             "noise_scales", "names " + format_value(n) + " twice");
  }
  const std::int64_t held_out = in.get_int("held_out_seeds", def.held_out_seeds);
  in.check(held_out >= 0 && held_out <= 1000, "held_out_seeds",
           "must be in [0, 1000], got " + std::to_string(held_out));
  def.held_out_seeds = static_cast<int>(held_out);

  // the base scenario must load with the overrides, and tells which metrics exist
  Scenario base;
  try {
    base = load_scenario_text(def.base_text, def.base_path, def.overrides);
  } catch (const InputError& e) {
    in.fail("base", std::string("(") + e.what() + ")");
  }
  const std::vector<std::string> metrics = base_metric_names(base);
  const auto known_metric = [&](const std::string& where, const std::string& m) {
    if (std::find(metrics.begin(), metrics.end(), m) != metrics.end()) return;
    std::string list;
    for (const auto& n : metrics) list += (list.empty() ? "" : ", ") + n;
    in.fail(where, "names no metric of the base scenario: \"" + m + "\" (it has " + list + ")");
  };

  if (const toml::array* list = array_of_tables(in, "parameter")) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const Entry e{in, table_at(in, *list, i, "parameter"),
                    "parameter[" + std::to_string(i) + "]."};
      e.allow({"key", "from", "to", "scale"});
      TuneParameter p;
      p.key = e.text("key", true);
      for (const TuneParameter& q : def.parameters) {
        in.check(q.key != p.key, e.where + "key", "names " + p.key + " twice");
      }
      in.check(p.key != "seed" && p.key != "sensors.noise_scale", e.where + "key",
               "cannot be \"" + p.key + "\": use the tuning file's seeds / noise_scales");
      const auto from = e.number("from"), to = e.number("to");
      if (!from) in.fail(e.where + "from", "is required");
      if (!to) in.fail(e.where + "to", "is required");
      p.from = *from;
      p.to = *to;
      in.check(p.from < p.to, e.where + "from",
               "must be below to (" + format_value(p.from) + " >= " + format_value(p.to) + ")");
      const std::string scale = e.text("scale", false, "linear");
      in.check(scale == "linear" || scale == "log", e.where + "scale",
               "must be \"linear\" or \"log\", got \"" + scale + "\"");
      p.log = scale == "log";
      in.check(!p.log || p.from > 0.0, e.where + "from",
               "must be > 0 on a log scale, got " + format_value(p.from));
      def.parameters.push_back(p);
    }
  }
  in.check(!def.parameters.empty(), "parameter", "needs at least one [[parameter]]");
  if (const toml::array* list = array_of_tables(in, "objective")) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const Entry e{in, table_at(in, *list, i, "objective"),
                    "objective[" + std::to_string(i) + "]."};
      e.allow({"metric", "maximize"});
      TuneObjective o;
      o.metric = e.text("metric", true);
      known_metric(e.where + "metric", o.metric);
      if (const toml::node* n = e.t.get("maximize")) {
        if (!n->is_boolean()) in.fail(e.where + "maximize", "must be true or false");
        o.maximize = *n->value<bool>();
      }
      def.objectives.push_back(o);
    }
  }
  in.check(!def.objectives.empty(), "objective", "needs at least one [[objective]]");
  in.check(
      def.algorithm == TuneAlgorithm::kNsga2 || def.objectives.size() == 1, "algorithm",
      "cmaes minimises one objective; use \"nsga2\" for " + std::to_string(def.objectives.size()));
  if (const toml::array* list = array_of_tables(in, "constraint")) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const Entry e{in, table_at(in, *list, i, "constraint"),
                    "constraint[" + std::to_string(i) + "]."};
      e.allow({"metric", "min", "max"});
      TuneConstraint c;
      c.metric = e.text("metric", true);
      known_metric(e.where + "metric", c.metric);
      if (const auto v = e.number("min")) c.min = *v;
      if (const auto v = e.number("max")) c.max = *v;
      in.check(std::isfinite(c.min) || std::isfinite(c.max), e.where + "min", "or max is required");
      in.check(c.min <= c.max, e.where + "min", "must not exceed max");
      def.constraints.push_back(c);
    }
  }
  if (const toml::array* list = array_of_tables(in, "reference")) {
    for (std::size_t i = 0; i < list->size(); ++i) {
      const Entry e{in, table_at(in, *list, i, "reference"),
                    "reference[" + std::to_string(i) + "]."};
      e.allow({"name", "values"});
      TuneReference r;
      r.name = e.text("name", true);
      const toml::array* values = e.t.get("values") ? e.t.get("values")->as_array() : nullptr;
      if (!values || values->size() != def.parameters.size()) {
        in.fail(e.where + "values", "must be a list of " + std::to_string(def.parameters.size()) +
                                        " numbers, one per [[parameter]]");
      }
      for (const toml::node& n : *values) {
        if (!(n.is_integer() || n.is_floating_point())) {
          in.fail(e.where + "values", "must be numbers");
        }
        const double v = *n.value<double>();
        in.check(std::isfinite(v), e.where + "values", "must be finite, got " + format_value(v));
        r.values.push_back(v);
      }
      def.references.push_back(r);
    }
  }
  in.reject_unknown();

  // every reference must make a valid scenario
  for (std::size_t i = 0; i < def.references.size(); ++i) {
    try {
      load_scenario_text(def.base_text, def.base_path,
                         parameter_overrides(def, def.references[i].values));
    } catch (const InputError& e) {
      throw InputError(path + ": reference[" + std::to_string(i) + "] (" +
                       def.references[i].name + "): " + e.what());
    }
  }
  // every parameter at both bounds must make a valid scenario (a bad key fails here)
  for (std::size_t i = 0; i < def.parameters.size(); ++i) {
    for (double u : {0.0, 1.0}) {
      std::vector<double> values;
      for (const TuneParameter& p : def.parameters) values.push_back(value_at(p, 0.5));
      values[i] = value_at(def.parameters[i], u);
      try {
        load_scenario_text(def.base_text, def.base_path, parameter_overrides(def, values));
      } catch (const InputError& e) {
        throw InputError(path + ": parameter[" + std::to_string(i) + "] (" + def.parameters[i].key +
                         "): " + e.what());
      }
    }
  }
  return def;
}

// --- TuneDb -------------------------------------------------------------------------------

TuneDb::TuneDb(sqlite3* db, std::string path) : db_(db), path_(std::move(path)) {}
TuneDb::TuneDb(TuneDb&& o) noexcept : db_(o.db_), path_(std::move(o.path_)), lock_fd_(o.lock_fd_) {
  o.db_ = nullptr;
  o.lock_fd_ = -1;
}
TuneDb& TuneDb::operator=(TuneDb&& o) noexcept {
  if (this != &o) {
    close();
    db_ = o.db_;
    path_ = std::move(o.path_);
    lock_fd_ = o.lock_fd_;
    o.db_ = nullptr;
    o.lock_fd_ = -1;
  }
  return *this;
}
TuneDb::~TuneDb() { close(); }

void TuneDb::close() {
  if (db_) sqlite3_close(db_);
  db_ = nullptr;
  if (lock_fd_ >= 0) ::close(lock_fd_);
  lock_fd_ = -1;
}

void TuneDb::exec(const std::string& sql) const {
  char* err = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string why = err ? err : "unknown error";
    sqlite3_free(err);
    throw std::runtime_error(path_ + ": " + why);
  }
}

TuneDb TuneDb::create(const std::string& path, const TuneDefinition& def) {
  create_sqlite_file(path, "tuning database", "give --resume to continue it, or another --db",
                     [&](const std::string& tmp) {
    TuneDb db(open_db(tmp, SQLITE_OPEN_READWRITE), tmp);
    std::string params, objectives;
    for (std::size_t i = 0; i < def.parameters.size(); ++i)
      params += ", u" + std::to_string(i) + " REAL";
    for (std::size_t i = 0; i < def.parameters.size(); ++i)
      params += ", x" + std::to_string(i) + " REAL";
    for (std::size_t i = 0; i < def.objectives.size(); ++i) {
      objectives +=
          ", objective" + std::to_string(i) + " REAL, fitness" + std::to_string(i) + " REAL";
    }
    db.exec(
        "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT);"
        "CREATE TABLE evaluations(evaluation INTEGER PRIMARY KEY" +
        params + objectives +
        ", violation REAL, trials INTEGER, ok INTEGER);"
        "CREATE TABLE trials(evaluation INTEGER, seed INTEGER, noise_scale REAL, status TEXT,"
        " message TEXT, metrics TEXT, PRIMARY KEY(evaluation, seed, noise_scale));");
    Statement s = prepare(db.db_, "INSERT INTO meta VALUES (?, ?)");
    for (const auto& [k, v] : std::vector<std::pair<std::string, std::string>>{
             {"kind", "pamsim tune"},
             {"tune_definition", def.canonical_json()},
             {"tune_file", def.file},
             {"pamsim_version", PAMSIM_VERSION},
             {"git_commit", build_info().git_commit},
             {"mujoco_version", build_info().mujoco_version},
             {"sundials_version", build_info().sundials_version},
             {"command_line", nlohmann::json(command_line()).dump()},
             {"created_utc", utc_timestamp()}}) {
      sqlite3_bind_text(s.get(), 1, k.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(s.get(), 2, v.c_str(), -1, SQLITE_TRANSIENT);
      if (sqlite3_step(s.get()) != SQLITE_DONE) throw std::runtime_error(tmp + ": cannot write");
      sqlite3_reset(s.get());
    }
  });
  return open_to_resume(path, def);
}

TuneDb TuneDb::open_to_resume(const std::string& path, const TuneDefinition& def) {
  TuneDb db(open_sqlite_file(path, DbAccess::kWrite, "tuning database"), path);
  if (db.meta("kind") != "pamsim tune") throw InputError(path + ": not a pamsim tuning database");
  if (db.meta("tune_definition") != def.canonical_json()) {
    throw InputError(path +
                     ": holds another tuning definition (a different file, base scenario "
                     "or setting); start a new --db");
  }
  db.lock_fd_ = take_lock(path);
  db.exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;");
  return db;
}

TuneDb TuneDb::open_existing(const std::string& path) {
  TuneDb db(open_sqlite_file(path, DbAccess::kRead, "tuning database"), path);
  if (db.meta("kind") != "pamsim tune") throw InputError(path + ": not a pamsim tuning database");
  return db;
}

bool TuneDb::is_tune_database(const std::string& path) {
  try {
    return TuneDb(open_sqlite_file(path, DbAccess::kRead, "database"), path).meta("kind") ==
           "pamsim tune";
  } catch (const std::exception&) {
    return false;   // the sweep reader says what is wrong with it
  }
}

std::string TuneDb::meta(const std::string& key) const {
  sqlite3_stmt* raw = nullptr;
  if (sqlite3_prepare_v2(db_, "SELECT value FROM meta WHERE key = ?", -1, &raw, nullptr) !=
      SQLITE_OK) {
    sqlite3_finalize(raw);
    return "";
  }
  Statement s(raw);
  sqlite3_bind_text(s.get(), 1, key.c_str(), -1, SQLITE_TRANSIENT);
  if (sqlite3_step(s.get()) != SQLITE_ROW) return "";
  const auto* text = sqlite3_column_text(s.get(), 0);
  return text ? reinterpret_cast<const char*>(text) : "";
}

std::vector<TuneEvaluation> TuneDb::evaluations() const {
  const TuneDefinition def = tune_definition_from_db(*this);
  const std::size_t n_x = def.parameters.size(), n_o = def.objectives.size();
  Statement s = prepare(db_, "SELECT * FROM evaluations ORDER BY evaluation");
  std::vector<TuneEvaluation> out;
  const auto real = [&](int col) {
    return sqlite3_column_type(s.get(), col) == SQLITE_NULL ? kNaN
                                                            : sqlite3_column_double(s.get(), col);
  };
  int rc;
  while ((rc = sqlite3_step(s.get())) == SQLITE_ROW) {
    TuneEvaluation e;
    int col = 0;
    e.index = sqlite3_column_int64(s.get(), col++);
    for (std::size_t i = 0; i < n_x; ++i) e.unit.push_back(real(col++));
    for (std::size_t i = 0; i < n_x; ++i) e.values.push_back(real(col++));
    for (std::size_t i = 0; i < n_o; ++i) {
      e.objectives.push_back(real(col++));
      e.fitness.push_back(real(col++));
    }
    e.violation = real(col++);
    e.trials = sqlite3_column_int(s.get(), col++);
    e.ok = sqlite3_column_int(s.get(), col++);
    out.push_back(e);
  }
  if (rc != SQLITE_DONE) {
    throw std::runtime_error(path_ + ": cannot read the evaluations (" + sqlite3_errmsg(db_) + ")");
  }
  return out;
}

void TuneDb::insert(const TuneEvaluation& e, const std::vector<TrialRow>& trials) {
  exec("BEGIN IMMEDIATE");
  try {
    std::string sql = "INSERT INTO evaluations VALUES (?";
    const std::size_t cells = e.unit.size() + e.values.size() + 2 * e.objectives.size() + 3;
    for (std::size_t i = 0; i < cells; ++i) sql += ", ?";
    Statement s = prepare(db_, sql + ")");
    int col = 1;
    const auto bind = [&](double v) {
      if (std::isfinite(v)) {
        sqlite3_bind_double(s.get(), col++, v);
      } else {
        sqlite3_bind_null(s.get(), col++);
      }
    };
    sqlite3_bind_int64(s.get(), col++, e.index);
    for (double v : e.unit) bind(v);
    for (double v : e.values) bind(v);
    for (std::size_t i = 0; i < e.objectives.size(); ++i) {
      bind(e.objectives[i]);
      bind(e.fitness[i]);
    }
    bind(e.violation);
    sqlite3_bind_int(s.get(), col++, e.trials);
    sqlite3_bind_int(s.get(), col++, e.ok);
    if (sqlite3_step(s.get()) != SQLITE_DONE) {
      throw std::runtime_error(path_ + ": cannot store evaluation " + std::to_string(e.index) +
                               " (" + sqlite3_errmsg(db_) + ")");
    }
    Statement t = prepare(db_, "INSERT INTO trials VALUES (?, ?, ?, ?, ?, ?)");
    for (const TrialRow& r : trials) {
      sqlite3_bind_int64(t.get(), 1, e.index);
      sqlite3_bind_int64(t.get(), 2, static_cast<sqlite3_int64>(r.seed));
      sqlite3_bind_double(t.get(), 3, r.noise_scale);
      sqlite3_bind_text(t.get(), 4, r.status.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(t.get(), 5, r.message.c_str(), -1, SQLITE_TRANSIENT);
      sqlite3_bind_text(t.get(), 6, r.metrics_json.c_str(), -1, SQLITE_TRANSIENT);
      if (sqlite3_step(t.get()) != SQLITE_DONE) {
        throw std::runtime_error(path_ + ": cannot store a trial (" + sqlite3_errmsg(db_) + ")");
      }
      sqlite3_reset(t.get());
    }
    exec("COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

TuneDefinition tune_definition_from_db(const TuneDb& db) {
  const auto j = nlohmann::json::parse(db.meta("tune_definition"), nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    throw InputError(db.path() + ": its tuning definition cannot be read");
  }
  try {
    TuneDefinition def;
    def.file = db.meta("tune_file");
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
    for (const auto& p : j.at("parameters")) {
      def.parameters.push_back({p.at("key"), p.at("from"), p.at("to"), p.at("log")});
    }
    for (const auto& o : j.at("objectives"))
      def.objectives.push_back({o.at("metric"), o.at("maximize")});
    for (const auto& c : j.at("constraints")) {
      TuneConstraint k;
      k.metric = c.at("metric");
      if (c.contains("min")) k.min = c.at("min");
      if (c.contains("max")) k.max = c.at("max");
      def.constraints.push_back(k);
    }
    for (const auto& r : j.at("references")) {
      def.references.push_back({r.at("name"), r.at("values").get<std::vector<double>>()});
    }
    return def;
  } catch (const nlohmann::json::exception& e) {
    // a damaged database, or one from a pamsim whose definition had other fields
    throw InputError(db.path() + ": its tuning definition cannot be read (" + e.what() + ")");
  }
}

// --- the run --------------------------------------------------------------------------------

namespace {

// Thrown out of a fitness call to stop the optimiser (a stop was requested).
struct StopTuning {};

// What pagmo's problem calls: evaluates (or answers from the database) one point of the unit
// box. pagmo copies the problem; every copy shares this.
struct Evaluator {
  const TuneDefinition* def = nullptr;
  TuneDb* db = nullptr;
  TuneRunOptions options;
  std::map<std::vector<double>, TuneEvaluation> cache;  // by the point (unit box)
  std::vector<TuneEvaluation> history;
  std::int64_t next_index = 0, cached = 0, total = 0, evaluated = 0;

  pagmo::vector_double fitness(const pagmo::vector_double& u) {
    const auto hit = cache.find(u);
    if (hit != cache.end()) {
      ++cached;
      if (options.on_evaluation) options.on_evaluation(++evaluated, total, true);
      return hit->second.fitness;
    }
    if (options.stop && options.stop->load()) throw StopTuning{};
    std::vector<double> values;
    for (std::size_t i = 0; i < u.size(); ++i) values.push_back(value_at(def->parameters[i], u[i]));
    const std::vector<TrialOutcome> trials =
        run_setting(*def, values, 0, def->seeds, options.threads);
    TuneEvaluation e = score(*def, values, trials);
    e.index = next_index++;
    e.unit = u;
    std::vector<TuneDb::TrialRow> rows;
    for (const TrialOutcome& t : trials) {
      nlohmann::json metrics = nlohmann::json::object();
      for (const Metric& m : t.summary.metrics) {
        if (std::isfinite(m.value)) metrics[m.name] = m.value;
      }
      rows.push_back({t.seed, t.noise_scale, t.summary.status, t.summary.message, metrics.dump()});
    }
    db->insert(e, rows);
    cache.emplace(u, e);
    history.push_back(e);
    if (options.on_evaluation) options.on_evaluation(++evaluated, total, false);
    return e.fitness;
  }
};

struct TuneProblem {
  std::shared_ptr<Evaluator> evaluator;
  std::size_t dimension = 1, objectives = 1;
  pagmo::vector_double fitness(const pagmo::vector_double& u) const {
    return evaluator->fitness(u);
  }
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    return {pagmo::vector_double(dimension, 0.0), pagmo::vector_double(dimension, 1.0)};
  }
  pagmo::vector_double::size_type get_nobj() const { return objectives; }
  std::string get_name() const { return "pamsim tune"; }
  // the copies share one Evaluator (its cache and database): never call them concurrently
  pagmo::thread_safety get_thread_safety() const { return pagmo::thread_safety::none; }
};

bool dominates(const TuneEvaluation& a, const TuneEvaluation& b) {
  bool better = false;
  for (std::size_t i = 0; i < a.fitness.size(); ++i) {
    if (a.fitness[i] > b.fitness[i]) return false;
    if (a.fitness[i] < b.fitness[i]) better = true;
  }
  return better;
}

}  // namespace

TuneRunResult run_tune(const TuneDefinition& def, TuneDb& db, const TuneRunOptions& options) {
  if (options.threads < 1) {
    throw InputError("--threads must be >= 1, got " + std::to_string(options.threads));
  }
  auto evaluator = std::make_shared<Evaluator>();
  evaluator->def = &def;
  evaluator->db = &db;
  evaluator->options = options;
  evaluator->total = static_cast<std::int64_t>(def.population) * (def.generations + 1);
  // a resume: the stored evaluations answer the replayed optimiser's calls
  for (const TuneEvaluation& e : db.evaluations()) {
    evaluator->cache.emplace(e.unit, e);  // the exact point pagmo asked for
    evaluator->next_index = std::max(evaluator->next_index, e.index + 1);
  }
  TuneRunResult result;
  try {
    pagmo::problem problem{TuneProblem{evaluator, def.parameters.size(), def.objectives.size()}};
    pagmo::population population{problem, def.population, static_cast<unsigned>(def.seed)};
    if (def.algorithm == TuneAlgorithm::kCmaes) {
      pagmo::algorithm algo{pagmo::cmaes(def.generations, -1, -1, -1, -1, 0.3, 0.0, 0.0, false,
                                         true, static_cast<unsigned>(def.seed))};
      population = algo.evolve(population);
    } else {
      pagmo::algorithm algo{
          pagmo::nsga2(def.generations, 0.95, 10.0, 0.01, 50.0, static_cast<unsigned>(def.seed))};
      population = algo.evolve(population);
    }
  } catch (const StopTuning&) {
    result.interrupted = true;
  }
  result.history = db.evaluations();
  result.cached = evaluator->cached;
  return result;
}

const TuneEvaluation* best_evaluation(const std::vector<TuneEvaluation>& history) {
  const TuneEvaluation* best = nullptr;
  for (const TuneEvaluation& e : history) {
    if (!best) {
      best = &e;
      continue;
    }
    const bool e_ok = e.violation == 0.0, b_ok = best->violation == 0.0;
    if (e_ok != b_ok) {
      if (e_ok) best = &e;
      continue;
    }
    if (!e_ok ? e.violation < best->violation : e.fitness[0] < best->fitness[0]) best = &e;
  }
  return best;
}

std::vector<const TuneEvaluation*> pareto_front(const std::vector<TuneEvaluation>& history) {
  std::vector<const TuneEvaluation*> front;
  for (const TuneEvaluation& e : history) {
    if (e.violation != 0.0) continue;
    bool dominated = false;
    for (const TuneEvaluation& other : history) {
      if (other.violation == 0.0 && dominates(other, e)) {
        dominated = true;
        break;
      }
    }
    if (!dominated) front.push_back(&e);
  }
  std::sort(front.begin(), front.end(), [](const TuneEvaluation* a, const TuneEvaluation* b) {
    return a->fitness[0] < b->fitness[0];
  });
  return front;
}

std::vector<HeldOutCheck> check_held_out(const TuneDefinition& def,
                                         const std::vector<TuneReference>& settings, int threads,
                                         bool tuning_seeds) {
  std::vector<HeldOutCheck> out;
  for (const TuneReference& s : settings) {
    const std::vector<TrialOutcome> trials =
        tuning_seeds ? run_setting(def, s.values, 0, def.seeds, threads)
                     : run_setting(def, s.values, kHeldOutSeedOffset, def.held_out_seeds, threads);
    const TuneEvaluation e = score(def, s.values, trials);
    HeldOutCheck c;
    c.name = s.name;
    c.values = s.values;
    c.objectives = e.objectives;
    for (const TuneConstraint& k : def.constraints)
      c.constraints.push_back(mean_metric(trials, k.metric));
    c.trials = e.trials;
    c.ok = e.ok;
    c.violation = e.violation;
    out.push_back(c);
  }
  return out;
}

std::string tune_evaluations_csv(const TuneDefinition& def,
                                 const std::vector<TuneEvaluation>& history) {
  std::string out = "evaluation";
  for (const TuneParameter& p : def.parameters) out += "," + p.key;
  for (const TuneObjective& o : def.objectives) out += "," + o.metric + "_mean";
  out += ",violation,feasible,trials,ok\n";
  const auto num = [](double v) { return std::isfinite(v) ? format_shortest(v) : std::string(); };
  for (const TuneEvaluation& e : history) {
    out += std::to_string(e.index);
    for (double v : e.values) out += "," + num(v);
    for (double v : e.objectives) out += "," + num(v);
    out += "," + num(e.violation) + "," + (e.violation == 0.0 ? "1" : "0") + "," +
           std::to_string(e.trials) + "," + std::to_string(e.ok) + "\n";
  }
  return out;
}

void write_tune_outputs(const TuneDefinition& def, const std::vector<TuneEvaluation>& history,
                        const StagedOutputs& out, bool plots) {
  if (history.empty()) throw InputError("no evaluation stored yet: nothing to report");
  const TuneEvaluation* best = best_evaluation(history);

  // convergence: every evaluation's first objective, and the best feasible so far
  {
    std::string all, running;
    double so_far = std::numeric_limits<double>::infinity();
    for (const TuneEvaluation& e : history) {
      all += gp_num(static_cast<double>(e.index)) + ' ' + gp_num(e.objectives[0]) + ' ' +
             (e.violation == 0.0 ? "1" : "0") + '\n';
      if (e.violation == 0.0) so_far = std::min(so_far, e.fitness[0]);
      if (std::isfinite(so_far)) {
        running += gp_num(static_cast<double>(e.index)) + ' ' +
                   gp_num(def.objectives[0].maximize ? -so_far : so_far) + '\n';
      }
    }
    GnuplotJob job;
    job.width_px = 1100;
    job.height_px = 700;
    job.data_files = {{"all.dat", all}, {"best.dat", running.empty() ? "0 nan\n" : running}};
    const std::string y = def.objectives[0].metric + " (mean over each evaluation's trials)";
    job.script = "set title " + gp_quote("pamsim tune: convergence") + "\nset grid\n" +
                 "set xlabel 'evaluation'\nset ylabel " + gp_quote(y) + "\n" +
                 "set key outside bottom center horizontal\n"
                 "plot 'all.dat' using 1:($3 == 1 ? $2 : 1/0) with points pt 7 ps 0.6 lc rgb "
                 "'#2471a3' title 'feasible', 'all.dat' using 1:($3 == 0 ? $2 : 1/0) with points "
                 "pt 6 ps 0.6 lc rgb '#999999' title 'breaks a constraint', 'best.dat' using 1:2 "
                 "with steps lw 2 lc rgb '#c0392b' title 'best feasible so far'\n";
    if (plots) run_gnuplot(out.path("convergence.png"), job);
  }
  if (def.objectives.size() > 1) {
    const std::vector<const TuneEvaluation*> front = pareto_front(history);
    std::string csv = "evaluation";
    for (const TuneParameter& p : def.parameters) csv += "," + p.key;
    for (const TuneObjective& o : def.objectives) csv += "," + o.metric + "_mean";
    csv += "\n";
    std::string dat;
    for (const TuneEvaluation* e : front) {
      csv += std::to_string(e->index);
      for (double v : e->values) csv += "," + format_shortest(v);
      for (double v : e->objectives) csv += "," + format_shortest(v);
      csv += "\n";
      dat += gp_num(e->objectives[0]) + ' ' + gp_num(e->objectives[1]) + '\n';
    }
    std::string all;
    for (const TuneEvaluation& e : history) {
      if (e.violation == 0.0) all += gp_num(e.objectives[0]) + ' ' + gp_num(e.objectives[1]) + '\n';
    }
    GnuplotJob job;
    job.width_px = 1000;
    job.height_px = 800;
    job.data_files = {{"front.dat", dat.empty() ? "nan nan\n" : dat},
                      {"all.dat", all.empty() ? "nan nan\n" : all}};
    job.script = "set title " + gp_quote("pamsim tune: Pareto front (feasible evaluations)") +
                 "\nset grid\nset xlabel " + gp_quote(def.objectives[0].metric) + "\nset ylabel " +
                 gp_quote(def.objectives[1].metric) +
                 "\nplot 'all.dat' with points pt 6 lc rgb '#999999' title 'evaluated', "
                 "'front.dat' with linespoints pt 7 lc rgb '#c0392b' title 'non-dominated'\n";
    if (plots) run_gnuplot(out.path("pareto.png"), job);
    write_file_atomically(out.path("pareto.csv"), csv);
  }
  write_file_atomically(out.path("evaluations.csv"),
                        tune_evaluations_csv(def, history));
  // the best setting as a ready scenario (paths relative to the output folder)
  std::vector<std::string> overrides = parameter_overrides(def, best->values);
  std::ostringstream header;
  header << "# pamsim tune: evaluation " << best->index << " of " << def.file << " ("
         << (best->violation == 0.0 ? "the best feasible" : "none feasible: the least violating")
         << "), " << def.objectives[0].metric << " mean " << format_value(best->objectives[0])
         << "\n";
  write_file_atomically(
      out.path("best.toml"),
      resolved_scenario_toml(def.base_text, def.base_path, overrides, out.dir(), header.str()));
}

}  // namespace pamsim
