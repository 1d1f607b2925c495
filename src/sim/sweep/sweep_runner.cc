// sweep_runner.cc: see sweep_runner.h.
#include "sim/sweep/sweep_runner.h"

#include <chrono>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "base/input_error.h"
#include "sim/core/runner.h"
#include "sim/scenario/scenario_file.h"
#include "sim/core/trial.h"

namespace pamsim {
namespace {

constexpr auto kProgressInterval = std::chrono::milliseconds(200);  // progress when idle

// A trial that could not run: status "failed" and why (the database stores no metrics).
TrialSummary failed_summary(std::uint64_t seed, const std::string& why) {
  TrialSummary s;
  s.seed = seed;
  s.status = "failed";
  s.message = why;
  return s;
}

}  // namespace

SweepTrialRunner::SweepTrialRunner(const SweepDefinition& sweep) : sweep_(sweep) {}
SweepTrialRunner::~SweepTrialRunner() = default;

void SweepTrialRunner::move_to(std::int64_t trial) {
  // trials of one point share a scenario, unless [[randomize]] draws each its own
  const std::int64_t scenario = sweep_.randomize.empty() ? trial / sweep_.seeds : trial;
  if (scenario == scenario_id_) return;
  scenario_id_ = -1;
  Scenario next =
      load_scenario_text(sweep_.base_text, sweep_.base_path, sweep_.trial_overrides(trial));
  if (!model_ || !same_trial_model(next, scenario_)) {
    model_ = std::make_unique<TrialModel>(load_trial_model(next));
  }
  scenario_ = std::move(next);
  scenario_id_ = scenario;
}

TrialRecord SweepTrialRunner::run(std::int64_t trial) {
  TrialRecord record;
  record.trial = trial;
  record.point = trial / sweep_.seeds;
  record.seed_index = trial % sweep_.seeds;
  const std::uint64_t seed = sweep_.seed_of(trial);
  try {
    move_to(trial);
    record.summary = run_trial(*model_, scenario_, seed, false).summary;
  } catch (const std::exception& e) {  // anything but a divergence (that is a status already)
    record.summary = failed_summary(seed, e.what());
  }
  return record;
}

void store_trials(const SweepDefinition& sweep, ResultsDb& db, std::vector<TrialRecord>& batch,
                  const SweepRunOptions& options, SweepRunResult& result) {
  db.insert(sweep, batch);
  for (const TrialRecord& r : batch) result.diverged += r.summary.status != "ok" ? 1 : 0;
  result.ran += static_cast<std::int64_t>(batch.size());
  batch.clear();
  if (options.on_progress) options.on_progress(result.already_done + result.ran);
}

namespace {

// What the worker threads and the writer (the calling thread) of run_sweep share.
struct SweepWork {
  SweepWork(const SweepDefinition& s, const SweepRunOptions& o, const std::vector<bool>& f,
            int workers)
      : sweep(s), options(o), finished(f), workers_left(workers) {}

  const SweepDefinition& sweep;
  const SweepRunOptions& options;
  const std::vector<bool>& finished;
  std::atomic<std::int64_t> next{0};
  std::atomic<bool> abort{false};  // the writer failed: workers stop too
  std::mutex mutex;
  std::condition_variable finished_cv;
  std::vector<TrialRecord> queue;  // finished, not yet committed
  int workers_left;

  bool stopping() const { return abort.load() || (options.stop && options.stop->load()); }

  // a worker thread: the next trial of the shard not yet finished, until none is left
  void work() {
    SweepTrialRunner runner(sweep);
    const std::int64_t total = sweep.trials();
    while (!stopping()) {
      const std::int64_t t = next++;
      if (t >= total) break;
      if (!options.shard.holds(t) || finished[static_cast<std::size_t>(t)]) continue;
      TrialRecord record = runner.run(t);
      std::lock_guard<std::mutex> lock(mutex);
      queue.push_back(std::move(record));
      finished_cv.notify_one();  // commit it now: a kill loses only the trials still running
    }
    std::lock_guard<std::mutex> lock(mutex);
    --workers_left;
    finished_cv.notify_one();
  }

  // the writer: commit whatever has finished, until every worker is done
  void commit_until_done(ResultsDb& db, SweepRunResult& result) {
    std::vector<TrialRecord> batch;
    for (bool last = false; !last;) {
      {
        std::unique_lock<std::mutex> lock(mutex);
        finished_cv.wait_for(lock, kProgressInterval,
                             [&] { return !queue.empty() || workers_left == 0; });
        batch.swap(queue);
        last = workers_left == 0;
      }
      store_trials(sweep, db, batch, options, result);
    }
  }
};

}  // namespace

SweepRunResult run_sweep(const SweepDefinition& sweep, ResultsDb& db,
                         const SweepRunOptions& options) {
  if (options.threads < 1) {
    throw InputError("--threads must be >= 1, got " + std::to_string(options.threads));
  }
  const auto start = std::chrono::steady_clock::now();
  const std::int64_t total = sweep.trials();
  const std::vector<bool> finished = db.finished_trials(total);
  SweepRunResult result;
  for (bool f : finished) result.already_done += f ? 1 : 0;

  SweepWork work(sweep, options, finished, options.threads);
  std::vector<std::thread> pool;
  for (int i = 0; i < options.threads; ++i) pool.emplace_back([&work] { work.work(); });
  try {
    work.commit_until_done(db, result);
  } catch (...) {
    work.abort = true;
    for (auto& t : pool) t.join();
    throw;
  }
  for (auto& t : pool) t.join();
  result.interrupted = result.already_done + result.ran < options.shard.trials_of(total);
  result.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace pamsim
