// runner.cc: see runner.h.
#include "sim/core/runner.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>

#include "base/input_error.h"

namespace pamsim {

int default_thread_count() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(n);
}

int resolve_thread_count(int requested) {
  if (requested < 0 || requested > kMaxThreads) {
    throw InputError("--threads must be 1 to " + std::to_string(kMaxThreads) +
                     " (or 0 for all cores), got " + std::to_string(requested));
  }
  return requested == 0 ? default_thread_count() : requested;
}

void parallel_for(int n, int threads, const std::function<void(int)>& job) {
  if (threads < 1) throw InputError("--threads must be >= 1, got " + std::to_string(threads));
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;

  // each worker takes the next index until none is left
  auto worker = [&] {
    for (int k = next++; k < n; k = next++) {
      try {
        job(k);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  const int n_threads = std::max(1, std::min(threads, n));
  std::vector<std::thread> pool;
  try {
    for (int i = 1; i < n_threads; ++i) pool.emplace_back(worker);
  } catch (const std::system_error&) {
    // out of threads: the ones started, and this one, do all the jobs
  }
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

std::vector<TrialResult> run_trials(const TrialModel& model, const Scenario& sc, int trials,
                                    int threads, bool keep_trajectory,
                                    const std::function<void(int)>& on_done) {
  if (trials < 1) throw InputError("--trials must be >= 1, got " + std::to_string(trials));
  if (threads < 1) throw InputError("--threads must be >= 1, got " + std::to_string(threads));
  std::vector<TrialResult> results(trials);
  std::mutex done_mutex;
  int done = 0;
  parallel_for(trials, threads, [&](int k) {
    results[k] = run_trial(model, sc, sc.seed + static_cast<std::uint64_t>(k), keep_trajectory);
    if (!on_done) return;
    const std::lock_guard<std::mutex> lock(done_mutex);
    on_done(++done);
  });
  return results;
}

}  // namespace pamsim
