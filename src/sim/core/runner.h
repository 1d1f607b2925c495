// runner.h: repeated trials of one scenario on a pool of threads. Trial k uses seed
// scenario.seed + k; each worker owns its mjData and CVODE context (inside run_trial), the
// mjModel is shared read-only, so results do not depend on the thread count.
#pragma once

#include <functional>
#include <vector>

#include "sim/core/scenario.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"

namespace pamsim {

// Default thread count: all cores.
int default_thread_count();

// The most worker threads a command takes: more would only add stacks and contention.
inline constexpr int kMaxThreads = 1024;

// A command's --threads: 0 means all cores; otherwise 1 .. kMaxThreads. Throws InputError
// "--threads must be ..., got N" for anything else.
int resolve_thread_count(int requested);

// Calls job(k) for k = 0 .. n-1 on `threads` threads (the caller's among them), each index
// once, in no particular order; job must write only its own results. The first exception
// a job throws is rethrown after every thread has stopped. If the system refuses a thread,
// the jobs run on those it gave (the caller's at least). Throws InputError if threads < 1.
void parallel_for(int n, int threads, const std::function<void(int)>& job);

// Runs `trials` trials with seeds seed..seed+trials-1 on `threads` threads; results in
// seed order. `on_done(n)`, if given, is called after each trial with the number finished so
// far, from one thread at a time. Throws InputError if trials < 1 or threads < 1.
std::vector<TrialResult> run_trials(const TrialModel& model, const Scenario& scenario, int trials,
                                    int threads, bool keep_trajectory = true,
                                    const std::function<void(int)>& on_done = {});

}  // namespace pamsim
