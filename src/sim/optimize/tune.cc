// tune.cc: see tune.h.
#include "sim/optimize/tune.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "base/format.h"
#include "base/input_error.h"
#include "base/no_value.h"
#include "sim/core/runner.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {
namespace {

struct TrialOutcome {
  std::uint64_t seed = 0;
  double noise_scale = 1.0;
  TrialSummary summary;
};

// The scenarios of a setting's trials: one per noise level, or with [[randomize]] one per
// trial (level-major), its seed index first_seed_offset + k % seeds drawing its arm.
std::vector<Scenario> setting_scenarios(const TuneDefinition& def,
                                        const std::vector<double>& values,
                                        std::uint64_t first_seed_offset, int seeds) {
  std::vector<Scenario> scenarios;
  const int per_level = def.randomize.empty() ? 1 : seeds;
  for (double noise : def.noise_scales) {
    for (int s = 0; s < per_level; ++s) {
      std::vector<std::string> o = def.overrides_at(values);
      o.push_back("sensors.noise_scale=" + format_number(noise));
      append_draws(def.randomize, def.randomize_seed,
                   static_cast<std::int64_t>(first_seed_offset) + s, &o);
      scenarios.push_back(load_scenario_text(def.base_text, def.base_path, o));
    }
  }
  return scenarios;
}

// Runs a setting's trials (seeds x noise levels) on the pool.
std::vector<TrialOutcome> run_setting(const TuneDefinition& def, const std::vector<double>& values,
                                      std::uint64_t first_seed_offset, int seeds, int threads) {
  const std::vector<Scenario> scenarios = setting_scenarios(def, values, first_seed_offset, seeds);
  std::vector<std::size_t> model_of;
  const std::vector<TrialModel> models = shared_trial_models(scenarios, &model_of);
  const int per_level = seeds;
  const bool per_trial = !def.randomize.empty();
  std::vector<TrialOutcome> out(def.noise_scales.size() * static_cast<std::size_t>(per_level));
  parallel_for(static_cast<int>(out.size()), threads, [&](int k) {
    const std::size_t level = static_cast<std::size_t>(k / per_level);
    const std::size_t which = per_trial ? static_cast<std::size_t>(k) : level;
    const Scenario& sc = scenarios[which];
    const std::uint64_t seed =
        sc.seed + first_seed_offset + static_cast<std::uint64_t>(k % per_level);
    TrialOutcome& t = out[static_cast<std::size_t>(k)];
    t.seed = seed;
    t.noise_scale = def.noise_scales[level];
    t.summary = run_trial(models[model_of[which]], sc, seed, /*keep_trajectory=*/false).summary;
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

// The tuning's objective for the search driver: a point's trials run and scored, stored
// with their metrics in the tuning database.
class TuningObjective final : public Objective {
 public:
  TuningObjective(const TuneDefinition& def, TuneDb& db, int threads)
      : def_(def), db_(db), threads_(threads) {}
  std::size_t dimension() const override { return def_.parameters.size(); }
  std::size_t objective_count() const override { return def_.objectives.size(); }

  Evaluation evaluate(std::int64_t index, const std::vector<double>& unit) override {
    std::vector<double> values;
    for (std::size_t i = 0; i < unit.size(); ++i)
      values.push_back(value_at(def_.parameters[i], unit[i]));
    const std::vector<TrialOutcome> trials = run_setting(def_, values, 0, def_.seeds, threads_);
    TuneEvaluation e = score(def_, values, trials);
    e.index = index;
    e.unit = unit;
    std::vector<TuneDb::TrialRow> rows;
    for (const TrialOutcome& t : trials) {
      nlohmann::json metrics = nlohmann::json::object();
      for (const Metric& m : t.summary.metrics) {
        if (std::isfinite(m.value)) metrics[m.name] = m.value;
      }
      rows.push_back({t.seed, t.noise_scale, t.summary.status, t.summary.message, metrics.dump()});
    }
    db_.insert(e, rows);
    return e;
  }

 private:
  const TuneDefinition& def_;
  TuneDb& db_;
  int threads_;
};

}  // namespace

TuneRunResult run_tune(const TuneDefinition& def, TuneDb& db, const TuneRunOptions& options) {
  if (options.threads < 1) {
    throw InputError("--threads must be >= 1, got " + std::to_string(options.threads));
  }
  TuningObjective objective(def, db, options.threads);
  SearchOptions search;
  search.stop = options.stop;
  search.on_evaluation = options.on_evaluation;
  const SearchResult found = run_search(def.search(), objective, db.evaluations(), search);
  TuneRunResult result;
  result.history = db.evaluations();
  result.cached = found.cached;
  result.interrupted = found.interrupted;
  return result;
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

}  // namespace pamsim
