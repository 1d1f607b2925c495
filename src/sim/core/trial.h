// trial.h: one trial of any scenario, the co-simulation loop (docs/ARCHITECTURE.md, "One trial"):
//   before each physics step: events due at this time fire (release a held body, add a
//     payload, switch the controller, end the trial); held bodies are put back in place;
//   mj_step1; at sim.control_hz: every muscle's sensors are sampled (sensing/sensing.h), the
//     controller turns the readings and the scheduled commands into valve commands, and one
//     log row is written (trial_log.h);
//   mj_step2 applies the PAM force law through the actuator callback with the pressures at
//     t; the chamber pressures advance over [t, t+dt] by CVODE (PneumaticSystem), driven by
//     the valve commands and the PAM lengths from MuJoCo;
//   after the step: events whose condition now holds fire (contact, joint or body past a
//     threshold); step-wise metrics see the joint;
// and the metric sets the scenario lists make the summary at the end (metrics.h).
// An optional observer (the video renderer) is shown the state at the times it asks for.
#pragma once

#include <cstdint>
#include <memory>
#include <limits>
#include <string>
#include <vector>

#include "embedded/pamctl.h"
#include "sensing/muscle_reading.h"
#include "sim/core/metrics.h"
#include "sim/core/scenario.h"
#include "sim/core/trial_log.h"
#include "sim/core/trial_model.h"

namespace pamsim {

struct TrialResult {
  TrialSummary summary;
  Trajectory trajectory;
};

// What a trial shows its observer: the state after a physics step (or the initial state),
// read-only and valid only during the call. Vectors are per muscle, model order.
struct TrialSnapshot {
  const mjModel* model = nullptr;
  const mjData* data = nullptr;
  double time_s = 0.0;
  bool hinge = true;                      // the joint's kind
  double joint_position_deg_or_mm = 0.0;  // a hinge's [deg], a slide's [mm]
  const std::vector<std::string>* labels = nullptr;
  const std::vector<double>* pressure_pa = nullptr;  // chamber pressures
  const std::vector<double>* command_pa = nullptr;   // valve commands
  // what the controller logs per muscle (its channels) and their values as of the last
  // control tick, [channel][muscle]
  const std::vector<ControllerChannel>* channels = nullptr;
  const std::vector<std::vector<double>>* channel_values = nullptr;
  // the control tick at which a window of the first window channel (a reflex's Ia) first
  // opened, NaN before (first_trigger_time_s)
  double first_trigger_s = std::numeric_limits<double>::quiet_NaN();
};

// How close d->time (which accumulates rounding) must come to an asked-for time to count as
// reaching it; observers count their frames with the same tolerance.
inline constexpr double kObservationToleranceS = 1e-9;

// Watches a trial without taking part in it: the trial runs bit-identically with or without
// one. run_trial shows it the initial state and then the state after every physics step
// whose time has reached next_observation_time_s() (within kObservationToleranceS); an
// observer that wants no more returns +infinity. Exceptions from observe() end the trial
// and propagate.
class TrialObserver {
 public:
  virtual ~TrialObserver() = default;
  virtual double next_observation_time_s() const = 0;
  virtual void observe(const TrialSnapshot& snapshot) = 0;
};

// Every control tick as the controller was handed it: the embedded controller's inputs
// (src/embedded/pamctl.h) exactly, and the commands the controller returned. Flat, per tick:
// time_s, enabled (0 or 1), then per muscle pressure_V, gauge_V, fiber_rate_m_s, p_tp_Pa,
// p_cmd_Pa (kPerMuscle values). `pamsim run --readings` writes it losslessly (readings.csv).
struct ControlLog {
  static constexpr int kPerTick = 2;
  static constexpr int kPerMuscle = 5;
  int muscle_count = 0;
  std::vector<double> values;
  std::size_t ticks() const {
    return values.size() / (kPerTick + kPerMuscle * static_cast<std::size_t>(muscle_count));
  }
};

// One control tick as a controller outside the process is handed it (`pamsim hil`): the
// embedded controller's inputs (src/embedded/pamctl.h), and the commands the scenario's own
// controller gave, which still runs beside it.
struct ControlTick {
  long index = 0;  // 0 at t = 0
  double time_s = 0.0;
  bool enabled = true;
  const std::vector<MuscleReading>* readings = nullptr;  // raw: pressure_sensor_v, gauge_v,
                                                         // fiber_rate_m_s
  const std::vector<double>* p_tp_pa = nullptr;          // the scheduled goal pressures
  const std::vector<double>* controller_pa = nullptr;    // the scenario's controller's
};

// Where the valve commands come from when not from the scenario's controller: at every
// control tick, after that controller ran, the source writes the commands to apply into
// *p_cmd_pa (one per muscle, model order). Returning false ends the trial at that tick with
// status "link_lost" and *why (its log holds the ticks before it).
class CommandSource {
 public:
  virtual ~CommandSource() = default;
  virtual bool command(const ControlTick& tick, std::vector<double>* p_cmd_pa,
                       std::string* why) = 0;
};

struct TrialOptions {
  bool keep_trajectory = true;
  TrialObserver* observer = nullptr;        // not owned; none by default (nothing to pay for)
  ControlLog* control_log = nullptr;        // not owned; filled at every control tick when given
  CommandSource* command_source = nullptr;  // not owned; the commands from outside
};

// The controller `scenario` runs on `model` as the embedded controller holds it (its
// estimators, calibrated gauges, filters, reflexes, pairs and valve range): "" when done, else
// the one-line reason it cannot run there (a controller kind without an embedded form).
std::string embedded_controller_config(const TrialModel& model, const Scenario& scenario,
                                       pamctl_config* config);

// The columns of the log a trial of `scenario` on `model` writes (trial_log.h), without
// running it.
LogLayout trial_log_layout(const TrialModel& model, const Scenario& scenario);

// Runs one trial of `scenario` with `seed` on `model` (shared, read-only; built by
// load_trial_model from the same scenario, or one for which same_trial_model holds).
// Never throws for a diverging simulation: it ends the trial with status "diverged".
// The summary's wall_time_s is the simulation's alone, without the observer's time.
TrialResult run_trial(const TrialModel& model, const Scenario& scenario, std::uint64_t seed,
                      const TrialOptions& options);
inline TrialResult run_trial(const TrialModel& model, const Scenario& scenario, std::uint64_t seed,
                             bool keep_trajectory = true) {
  TrialOptions options;
  options.keep_trajectory = keep_trajectory;
  return run_trial(model, scenario, seed, options);
}

// What a caller stepping a trial sees after a step (SteppedTrial::observe) is a
// TrialObservation (trial_channels.h).

// A trial advanced by its caller one control period at a time, for a controller outside
// pamsim (the Python module's Trial, a user's C++). Each step runs the next control tick
// and the physics steps up to the following one; at that tick `commands_pa` (valve commands,
// one per muscle, model order), when given, replace the scenario's controller's (which still
// sees the sensors, so its state and the log's estimates stay as in run_trial). Stepped
// with no commands until done, a trial is the one run_trial runs, bit for bit: run_trial
// drives the same loop.
class SteppedTrial {
 public:
  // `model` (read-only) must outlive the trial; the scenario is copied.
  SteppedTrial(const TrialModel& model, const Scenario& scenario, std::uint64_t seed);
  ~SteppedTrial();
  SteppedTrial(const SteppedTrial&) = delete;
  SteppedTrial& operator=(const SteppedTrial&) = delete;

  // Starts the trial again from its initial state with `seed` (the sensors' noise).
  void reset(std::uint64_t seed);
  // One control period; returns false once the trial has ended (its duration reached, an
  // event ended it, or it diverged: finish() says which). Throws InputError for a command
  // count that is not the muscle count.
  bool step(const std::vector<double>* commands_pa = nullptr);
  bool done() const;
  TrialObservation observe() const;
  // The state as a TrialObserver sees it (a video's frame draws it); valid until the next
  // step, reset() or finish().
  TrialSnapshot snapshot();
  const Scenario& scenario() const;
  double time_s() const;  // the next control tick's time (observe().time_s)

  // Live changes (`pamsim view`), each from the next control tick, exactly as the scenario's
  // own events make them there: a `set` event at that time gives the same trial, bit for bit.
  // Fires the scenario's event `name` now (a release: the mass drops); false when it has
  // fired already or the trial is done; throws InputError for a name the scenario lacks.
  bool fire_event(const std::string& name);
  // The controller on (its reflexes) or off (the schedules pass through): controller_on/off.
  void set_controller_enabled(bool on);
  bool controller_enabled() const;
  // The controller's settings from a configuration of the scenario's kind
  // (load_controller_settings), its state kept: a `set` event.
  void retune_controller(const ControllerConfig& config);

  // The summary and the log of the trial so far (ended early if not done); reset() to run
  // another.
  TrialResult finish();

 private:
  struct State;
  const TrialModel& model_;
  std::unique_ptr<State> state_;
};

}  // namespace pamsim
