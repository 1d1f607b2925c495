// tune.h: automatic tuning of a scenario's settings (`pamsim tune`): a tuning file names the
// base scenario, the free parameters with bounds, the objectives and constraints built from
// trial metrics averaged over seeds and sensor-noise levels, and the algorithm, CMA-ES for
// one objective or NSGA-II for a Pareto front, both from pagmo2. Every evaluation (its
// parameters, objectives and per-trial metrics) is stored in SQLite as it finishes; the
// optimiser is deterministic for its seed, so a run interrupted at any point is resumed by
// replaying it with the stored evaluations answered from the database: nothing is evaluated
// twice (a point the optimiser proposes again is answered the same way, so the database
// holds distinct points) and the result is the uninterrupted run's. An evaluation's trials
// run in parallel on the trial pool (parallel_for); pagmo proposes the points one by one.
//
// Tuning file keys (paths relative to the file):
//   base              scenario file, required
//   overrides         scenario overrides at every evaluation ("key=value" strings)
//   algorithm         "cmaes" (exactly one objective) | "nsga2" (one or more)
//   generations       >= 1; population: >= 5 (cmaes), a multiple of 4 >= 8 (nsga2)
//   seed              the optimiser's seed, >= 0
//   seeds             trials per noise level of an evaluation (seeds base.seed ..), >= 1
//   noise_scales      sensors.noise_scale levels each evaluation averages over; default [1]
//   held_out_seeds    seeds of the final check (base.seed + 1000 ..), >= 0; default 20
//   [[parameter]]     key (a scenario key), from < to, scale = "linear" | "log" (from > 0)
//   [[objective]]     metric (a summary metric), maximize = false
//   [[constraint]]    metric, min and/or max: on the metric's mean over an evaluation's trials
//   [[reference]]     name, values = [one per parameter]: settings checked beside the best
// A metric's value for an evaluation is its mean over the trials that ran to the end with a
// finite value. Objectives are minimised (a maximised one negated); an evaluation that
// breaks a constraint (a constraint metric with no value counts 1), or has a trial that did
// not run to the end (1 each), gets kTunePenalty per unit of violation added to every
// objective. CMA-ES runs all its generations (no tolerance stop).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "sim/io/plot.h"   // plot_file_names

struct sqlite3;

namespace pamsim {

class StagedOutputs;

inline constexpr double kTunePenalty = 1000.0;

struct TuneParameter {
  std::string key;
  double from = 0.0, to = 0.0;
  bool log = false;
};

struct TuneObjective {
  std::string metric;
  bool maximize = false;
};

struct TuneConstraint {
  std::string metric;
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
};

struct TuneReference {
  std::string name;
  std::vector<double> values;
};

enum class TuneAlgorithm { kCmaes, kNsga2 };

struct TuneDefinition {
  std::string file;
  std::string base_path, base_text;
  std::vector<std::string> overrides;
  TuneAlgorithm algorithm = TuneAlgorithm::kCmaes;
  unsigned generations = 10, population = 8;
  std::uint64_t seed = 1;
  int seeds = 3;
  std::vector<double> noise_scales{1.0};
  int held_out_seeds = 20;
  std::vector<TuneParameter> parameters;
  std::vector<TuneObjective> objectives;
  std::vector<TuneConstraint> constraints;
  std::vector<TuneReference> references;

  // Everything that decides the evaluations, as canonical JSON (stored; a resume must match).
  std::string canonical_json() const;
};

// Reads and validates the file, the base scenario (with the overrides, and with each
// parameter at both bounds) and the metric names. Throws InputError "<file>: <key> <problem>".
TuneDefinition load_tune_definition(const std::string& path);

// One evaluation: the parameter values, the mean of each objective's metric over its trials
// (as the metric reads, not negated), the constraint violation, and the fitness pagmo saw.
struct TuneEvaluation {
  std::int64_t index = 0;
  std::vector<double> unit;  // the optimiser's point in [0, 1]^n (the resume's key)
  std::vector<double> values;
  std::vector<double> objectives;
  double violation = 0.0;       // sum over constraints and failed trials, 0: feasible
  std::vector<double> fitness;  // objectives (negated if maximised) + penalty
  int trials = 0, ok = 0;
};

// The database: meta(key, value), evaluations(evaluation, <unit point>, <parameters>,
// <objectives and fitness>, violation, trials, ok), trials(evaluation, seed, noise_scale, status,
// message, metrics JSON). Written by one process at a time (an flock), in WAL mode with full sync,
// one transaction per evaluation.
class TuneDb {
 public:
  // Creates `path` (refused if it exists), or opens it to resume (refused if it holds
  // another definition or is being written).
  static TuneDb create(const std::string& path, const TuneDefinition& def);
  static TuneDb open_to_resume(const std::string& path, const TuneDefinition& def);
  static TuneDb open_existing(const std::string& path);  // read-only
  // True if `path` is a pamsim tuning database (for `pamsim report`).
  static bool is_tune_database(const std::string& path);

  TuneDb(TuneDb&& other) noexcept;
  TuneDb& operator=(TuneDb&& other) noexcept;
  TuneDb(const TuneDb&) = delete;
  TuneDb& operator=(const TuneDb&) = delete;
  ~TuneDb();

  const std::string& path() const { return path_; }
  std::string meta(const std::string& key) const;
  std::vector<TuneEvaluation> evaluations() const;
  struct TrialRow {
    std::uint64_t seed = 0;
    double noise_scale = 1.0;
    std::string status, message, metrics_json;
  };
  void insert(const TuneEvaluation& evaluation, const std::vector<TrialRow>& trials);

 private:
  TuneDb(sqlite3* db, std::string path);
  void exec(const std::string& sql) const;
  void close();

  sqlite3* db_ = nullptr;
  std::string path_;
  int lock_fd_ = -1;
};

struct TuneRunOptions {
  int threads = 1;
  const std::atomic<bool>* stop = nullptr;  // set: finish the evaluation in flight, then stop
  std::function<void(std::int64_t evaluated, std::int64_t total, bool cached)> on_evaluation;
};

struct TuneRunResult {
  std::vector<TuneEvaluation> history;  // in evaluation order
  std::int64_t cached = 0;              // answered from the database (a resume)
  bool interrupted = false;
};

// Runs (or resumes) the optimisation into `db`.
TuneRunResult run_tune(const TuneDefinition& def, TuneDb& db, const TuneRunOptions& options);

// The best feasible evaluation by the first objective (the least violating if none is
// feasible); the non-dominated feasible evaluations (several objectives).
const TuneEvaluation* best_evaluation(const std::vector<TuneEvaluation>& history);
std::vector<const TuneEvaluation*> pareto_front(const std::vector<TuneEvaluation>& history);

// A setting checked on held-out seeds: the mean of each objective and constraint metric,
// trials that ran, trials that broke a constraint.
struct HeldOutCheck {
  std::string name;
  std::vector<double> values;
  std::vector<double> objectives, constraints;
  int trials = 0, ok = 0;
  double violation = 0.0;
};
// On the held-out seeds (base.seed + 1000 ..., def.held_out_seeds of them), or with
// `tuning_seeds` on the seeds every evaluation used.
std::vector<HeldOutCheck> check_held_out(const TuneDefinition& def,
                                         const std::vector<TuneReference>& settings, int threads,
                                         bool tuning_seeds = false);

// The files write_tune_outputs writes (what `pamsim report` on a tuning database replaces),
// and with pamsim tune's own tuning_seeds.csv and held_out.csv (what `pamsim tune` replaces:
// a report must not remove the held-out checks it does not rerun).
inline const std::vector<std::string> kTuneReportOutputs = [] {
  std::vector<std::string> names = {"best.toml", "evaluations.csv", "pareto.csv"};
  for (const std::string& plot : plot_file_names({"convergence.png", "pareto.png"})) {
    names.push_back(plot);
  }
  return names;
}();
inline const std::vector<std::string> kTuneOutputs = [] {
  std::vector<std::string> names = kTuneReportOutputs;
  names.insert(names.end(), {"tuning_seeds.csv", "held_out.csv"});
  return names;
}();

// best.toml (the base scenario with the best values, ready for `pamsim run` from the output
// folder), evaluations.csv, convergence.png, and with several objectives pareto.csv and
// pareto.png, into the staging folder of `out` (published by the caller with the rest);
// without `plots`, no PNG.
void write_tune_outputs(const TuneDefinition& def, const std::vector<TuneEvaluation>& history,
                        const StagedOutputs& out, bool plots = true);
std::string tune_evaluations_csv(const TuneDefinition& def,
                                 const std::vector<TuneEvaluation>& history);

// The definition stored in a tuning database (for `pamsim report`), with its file as given.
TuneDefinition tune_definition_from_db(const TuneDb& db);

}  // namespace pamsim
