// trial.h: one falling-mass trial, the co-simulation loop of DESIGN.md "One trial":
//   physics at sim.timestep_s: chamber pressures advance over [t, t+dt] by CVODE
//   (PneumaticSystem) driven by the valve commands and the PAM lengths from MuJoCo; mj_step
//   applies the PAM force law through the actuator callback with the pressures at t;
//   control at sim.control_hz: the controller samples the plant, returns valve commands;
//   logging at the control rate; metrics at the end.
// An optional observer (the video renderer) is shown the state at the times it asks for.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "sim/core/arm_model.h"
#include "sim/io/scenario.h"

namespace pamsim {

// The trajectory, one row per control tick; columns named by trajectory_columns().
struct Trajectory {
  std::vector<std::string> columns;
  std::vector<double> values;   // row-major
  std::size_t rows() const { return columns.empty() ? 0 : values.size() / columns.size(); }
  double at(std::size_t row, std::size_t col) const { return values[row * columns.size() + col]; }
  std::size_t column(const std::string& name) const;   // throws std::out_of_range
};

const std::vector<std::string>& trajectory_columns();

// Metrics of summary.json. NaN where an event did not happen (written as null).
struct TrialSummary {
  std::string status = "ok";   // "ok" | "diverged"
  std::string message;         // why, when not ok
  std::uint64_t seed = 0;
  double start_angle_deg = 0;   // at the drop
  double min_angle_deg = 0;     // after the drop
  double min_angle_time_s = 0;
  double peak_drop_deg = 0;     // start - min
  double final_angle_deg = 0;
  double impact_time_s = 0;
  long steps = 0;
  double sim_time_s = 0;
  double wall_time_s = 0;       // the simulation loop alone
  double realtime_factor = 0;   // sim_time / wall_time
  // reflex (issue 4)
  int reflex_triggers_ago = 0;
  int reflex_triggers_anta = 0;
  double first_trigger_time_s = 0;
  int mistrips = 0;             // triggers before the impact
  double recovery_time_s = 0;   // impact until the angle stays within 2 deg of its final value
  double length_est_rmse_mm = 0;
  double length_est_max_error_mm = 0;
  // solver statistics
  long cvode_steps = 0;
  long cvode_rhs_evals = 0;
};

struct TrialResult {
  TrialSummary summary;
  Trajectory trajectory;
};

// What a trial shows its observer: the state after a physics step (or the initial state),
// read-only and valid only during the call.
struct TrialSnapshot {
  const mjModel* model = nullptr;
  const mjData* data = nullptr;
  double time_s = 0.0;
  double angle_deg = 0.0;
  std::array<double, kMuscleCount> pressure_pa{};   // chamber pressures
  std::array<double, kMuscleCount> command_pa{};    // valve commands
  std::array<bool, kMuscleCount> reflex_active{};   // as of the last control tick
};

// Watches a trial without taking part in it: the trial runs bit-identically with or without
// one. run_trial shows it the initial state and then the state after every physics step
// whose time has reached next_observation_time_s() (within 1 ns); an observer that wants
// no more returns +infinity. Exceptions from observe() end the trial and propagate.
// How close d->time (which accumulates rounding) must come to an asked-for time to count as
// reaching it; observers count their frames with the same tolerance.
inline constexpr double kObservationToleranceS = 1e-9;

class TrialObserver {
 public:
  virtual ~TrialObserver() = default;
  virtual double next_observation_time_s() const = 0;
  virtual void observe(const TrialSnapshot& snapshot) = 0;
};

struct TrialOptions {
  bool keep_trajectory = true;
  TrialObserver* observer = nullptr;   // not owned; none by default (nothing to pay for)
};

// Runs one trial of `scenario` with `seed` on `arm` (shared, read-only).
// Never throws for a diverging simulation: it ends the trial with status "diverged".
// The summary's wall_time_s is the simulation's alone, without the observer's time.
TrialResult run_trial(const ArmModel& arm, const Scenario& scenario, std::uint64_t seed,
                      const TrialOptions& options);
inline TrialResult run_trial(const ArmModel& arm, const Scenario& scenario, std::uint64_t seed,
                             bool keep_trajectory = true) {
  TrialOptions options;
  options.keep_trajectory = keep_trajectory;
  return run_trial(arm, scenario, seed, options);
}

}  // namespace pamsim
