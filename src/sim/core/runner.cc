// runner.cc: see runner.h.
#include "sim/core/runner.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "pam_actuator/input_error.h"

namespace pamsim {

ArmModel load_arm_for(const Scenario& sc) {
  const ArmCalibration calibration = load_calibration(sc.calibration_file);
  ArmModel arm = load_arm_model(sc.model_file, sc.pam, calibration, sc.drop_mass_kg);
  arm.model->opt.timestep = sc.timestep_s;   // the scenario's step, not the MJCF's
  return arm;
}

bool same_arm(const Scenario& a, const Scenario& b) {
  return a.model_file == b.model_file && a.agonist_params == b.agonist_params &&
         a.antagonist_params == b.antagonist_params && a.calibration_file == b.calibration_file &&
         a.drop_mass_kg == b.drop_mass_kg && a.timestep_s == b.timestep_s;
}

int default_thread_count() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : static_cast<int>(n);
}

std::vector<TrialResult> run_trials(const ArmModel& arm, const Scenario& sc, int trials,
                                    int threads, bool keep_trajectory) {
  if (trials < 1) throw InputError("--trials must be >= 1, got " + std::to_string(trials));
  if (threads < 1) throw InputError("--threads must be >= 1, got " + std::to_string(threads));
  std::vector<TrialResult> results(trials);
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;

  // each worker takes the next trial index until none is left
  auto worker = [&] {
    for (int k = next++; k < trials; k = next++) {
      try {
        results[k] = run_trial(arm, sc, sc.seed + static_cast<std::uint64_t>(k), keep_trajectory);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  const int n_threads = std::min(threads, trials);
  std::vector<std::thread> pool;
  for (int i = 1; i < n_threads; ++i) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  return results;
}

}  // namespace pamsim
