// tune.h: automatic tuning of a scenario's settings (`pamsim tune`), the first client of the
// search driver (optimizer.h): a tuning file (tuning_file.h) names the base scenario, the
// free parameters, the objectives and constraints built from trial metrics averaged over
// seeds and sensor-noise levels, and the algorithm; every evaluation (its parameters,
// objectives and per-trial metrics) is stored in the tuning database (tune_db.h) as it
// finishes, so a run interrupted at any point resumes where it stopped with the
// uninterrupted run's result. An evaluation's trials run in parallel on the trial pool.
//
// A metric's value for an evaluation is its mean over the trials that ran to the end with a
// finite value. Objectives are minimised (a maximised one negated); an evaluation that
// breaks a constraint (a constraint metric with no value counts 1), or has a trial that did
// not run to the end (1 each), gets kTunePenalty per unit of violation added to every
// objective.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sim/optimize/optimizer.h"
#include "sim/optimize/tune_db.h"
#include "sim/optimize/tuning_file.h"

namespace pamsim {

inline constexpr double kTunePenalty = 1000.0;

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

}  // namespace pamsim
