// runner.h: repeated trials of one scenario on a pool of threads. Trial k uses seed
// scenario.seed + k; each worker owns its mjData and CVODE context (inside run_trial), the
// mjModel is shared read-only, so results do not depend on the thread count.
#pragma once

#include <vector>

#include "sim/core/arm_model.h"
#include "sim/io/scenario.h"
#include "sim/core/trial.h"

namespace pamsim {

// The arm for a scenario: its MJCF, PAM parameters, calibration and falling mass.
ArmModel load_arm_for(const Scenario& scenario);

// True if two scenarios build the same arm (load_arm_for reads the same files and values),
// so a worker can keep its arm when a sweep moves to a point that changes only other keys.
bool same_arm(const Scenario& a, const Scenario& b);

// Default thread count: all cores.
int default_thread_count();

// Runs `trials` trials with seeds seed..seed+trials-1 on `threads` threads; results in
// seed order. Throws InputError if trials < 1 or threads < 1.
std::vector<TrialResult> run_trials(const ArmModel& arm, const Scenario& scenario, int trials,
                                    int threads, bool keep_trajectory = true);

}  // namespace pamsim
