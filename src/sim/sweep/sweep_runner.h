// sweep_runner.h: runs a sweep's unfinished trials on a pool of worker threads and streams
// each result into the results database. Every worker owns its model (mjModel, reloaded
// only when a point changes it, see same_trial_model) and creates a fresh mjData and CVODE context
// for each trial inside run_trial, so a trial's result depends only on its point and seed,
// never on the thread that ran it or on the trials before it. The calling thread is the only
// writer: as soon as trials finish it commits them (all that finished meanwhile in one
// transaction), so memory holds only the trials waiting for that commit and a kill loses only
// the trials still running.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "sim/core/scenario.h"
#include "sim/sweep/results_db.h"
#include "sim/sweep/sweep.h"

namespace pamsim {

struct TrialModel;

// Runs single trials of a sweep on the calling thread (one runner per thread). It keeps the
// scenario and model of the point it ran last (of the trial, when the sweep draws
// [[randomize]] values per trial), reloading the model only when a scenario changes it; each trial
// gets a fresh mjData and CVODE context, so a record depends only on its trial number. A trial that
// cannot run is returned with status "failed" and the reason.
class SweepTrialRunner {
 public:
  explicit SweepTrialRunner(const SweepDefinition& sweep);
  ~SweepTrialRunner();
  TrialRecord run(std::int64_t trial);

 private:
  void move_to(std::int64_t trial);

  const SweepDefinition& sweep_;
  std::int64_t scenario_id_ = -1;  // the point (or trial) scenario_ was made for
  Scenario scenario_;
  std::unique_ptr<TrialModel> model_;
};

struct SweepRunOptions {
  int threads = 1;
  SweepShard shard;  // the trials to run: the whole sweep, or one shard of it
  // Set (e.g. by a SIGINT handler) to stop: trials in flight finish and are committed,
  // no new one starts.
  const std::atomic<bool>* stop = nullptr;
  // Called on the calling thread after each commit with the trials stored so far.
  std::function<void(std::int64_t stored)> on_progress;
};

struct SweepRunResult {
  std::int64_t already_done = 0;  // stored before this run (--resume)
  std::int64_t ran = 0;           // run and stored now
  std::int64_t diverged = 0;      // of those, status "diverged" or "failed"
  bool interrupted = false;       // stopped before every trial was stored
  std::string incomplete_reason;  // why, when not stopped by options.stop (MPI ranks)
  double wall_time_s = 0;
};

// Stores `batch` in `db` in one transaction, counts it into `result` (ran, diverged) and
// reports the trials stored so far to options.on_progress; empties `batch`. For the runners.
void store_trials(const SweepDefinition& sweep, ResultsDb& db, std::vector<TrialRecord>& batch,
                  const SweepRunOptions& options, SweepRunResult& result);

// Runs every trial of `sweep` (of `options.shard`) not yet in `db`. Trial failures (divergence, an
// exception in a trial) are stored with their status and message; the sweep goes on. Throws
// InputError if threads < 1, std::runtime_error if the database cannot be written.
SweepRunResult run_sweep(const SweepDefinition& sweep, ResultsDb& db,
                         const SweepRunOptions& options);

}  // namespace pamsim
