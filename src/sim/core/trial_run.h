// trial_run.h: the TrialRun behind run_trial (trial.h), internal to src/sim/core: one
// trial from start to summary, one method per phase of a physics step. trial.cc sets it up
// and runs it; trial_step.cc holds the phases.
#pragma once

#include <array>
#include <chrono>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "pam_actuator/avbdl.h"
#include "pneumatics/pneumatics.h"
#include "sensing/sensing.h"
#include "sim/core/trial.h"

namespace pamsim {

// A trial's mjData. Each thread keeps the one it used last and lends it to its next trial
// on the same TrialModel, reset by mj_resetData (what mj_makeData does after allocating, so
// the trial is bit-identical): allocating and zeroing a fresh arena every trial page-faulted
// it in anew (5 % of the loop's time). A model copied for the trial, or a data already lent
// (a trial inside a trial), gets its own.
class TrialData {
 public:
  // `stays_on_thread`: the trial is run, and destroyed, on the thread that makes it (run_trial),
  // so it may borrow that thread's data; a SteppedTrial, which its caller may step and reset
  // from any thread (a thread pool), owns its data.
  TrialData(const TrialModel& model, const mjModel* m, bool stays_on_thread);
  ~TrialData();
  TrialData(const TrialData&) = delete;
  TrialData& operator=(const TrialData&) = delete;
  mjData* get() const { return d_; }

 private:
  MjDataPtr own_;
  mjData* d_ = nullptr;
  bool borrowed_ = false;
};

// What a trial of `sc` on `tm` gives its controller's kind (ControllerConfig).
ControllerSetup controller_setup(const TrialModel& tm, const Scenario& sc);

// One trial from start to summary; each private method is one phase of a physics step.
// run() is begin(), step() until it returns false, end(); SteppedTrial calls them itself.
class TrialRun {
 public:
  TrialRun(const TrialModel& tm, const Scenario& sc, std::uint64_t seed, const TrialOptions& opt,
           bool stays_on_thread = true);
  TrialResult run();

  void begin();       // the start state; the observer's first look
  bool step();        // one physics step (a control tick first when due); false: ended
  TrialResult end();  // the summary (and the log); the run is spent
  bool ended() const { return ended_ || step_ >= n_steps_; }
  bool control_due() const { return step_ % control_every_ == 0; }
  // Valve commands [Pa] that replace the controller's at the next control ticks (null: the
  // controller's); the pointer must stay valid while set.
  void set_external_commands(const std::vector<double>* p_cmd_pa) { external_pa_ = p_cmd_pa; }
  TrialObservation observe() const;
  // Live changes (SteppedTrial's), each as the scenario's events make it at this step.
  bool fire_now(std::size_t event);
  void set_controller_enabled(bool on) { controller_enabled_ = on; }
  bool controller_enabled() const { return controller_enabled_; }
  double observe_time_s() const { return time_at(step_); }
  void retune_controller(const ControllerConfig& config) {
    config.retune(*controller_, controller_setup(tm_, sc_));
  }
  // The state as an observer sees it (trial.h); valid until the next step.
  TrialSnapshot snapshot();

 private:
  void start_state();
  bool before_step(double t);   // false: an event ended the trial
  bool control_tick(double t);  // false: the controller failed (diverged)
  bool physics_step(double t);  // false: the step diverged
  bool after_step();            // false: an event ended the trial
  void fire(std::size_t k, double t);
  bool condition_holds(std::size_t k) const;
  void hold_bodies();
  bool first_window_open() const;  // a window of the first window channel is open
  bool source_command(double t);   // options_.command_source's commands; false: it ended
  void log_control(double t);      // one tick into options_.control_log
  void log_row(double t);
  void show_observer();
  double joint_position() const { return d_->qpos[tm_.joint.qpos]; }
  void set_status(const std::string& status, const std::string& why, double t);
  TrialSummary finish(long steps, std::chrono::steady_clock::duration wall);

  const TrialModel& tm_;
  const Scenario& sc_;
  const TrialOptions& options_;
  MjModelPtr own_model_;  // a copy, only when events change the model
  mjModel* mutable_model_ = nullptr;
  const mjModel* m_;
  TrialData data_;  // this thread's mjData for the model, reset
  mjData* d_;
  const std::size_t n_;  // muscles
  const std::vector<std::string> labels_;
  const std::vector<double> start_p_pa_;  // the schedules at t = 0
  PneumaticSystem pneumatics_;
  SensorSuite sensors_;
  std::unique_ptr<Controller> controller_;
  std::vector<std::unique_ptr<MetricSet>> metrics_;
  std::vector<MetricSet*> step_metrics_;
  LogLayout layout_;
  std::vector<ControllerChannel> channels_;  // what the controller logs per muscle
  std::vector<ControllerEvent> events_;      // and the events it records
  TrialResult result_;

  // One muscle's state the loop keeps from one physics step to the next, its own.
  struct MuscleLoopState {
    double length_m = 0.0;        // at the last physics step
    FreeLengthTrack free_length;  // its last free length (avbdl.h)
    double peak_tension_n = 0.0;  // the largest pull of any physics step
    bool has_history = false;     // its plant has a history (slip, relaxation)
  };

  // per tick and per step state, allocated once; the vectors below are handed on whole (to
  // the sensors, the controller, the observer), the rest is in muscle_
  std::vector<MuscleLoopState> muscle_;  // per muscle, model order
  std::vector<MuscleTruth> truth_;
  std::vector<MuscleReading> readings_;
  std::vector<double> p_tp_pa_;
  ControlOutput out_;
  TrialObservation tick_;  // the state the log's row is read from (trial_channels.h)
  std::vector<double> row_;
  std::vector<double> pressure_pa_, command_pa_;
  std::vector<double> source_pa_;  // the command source's commands
  double first_trigger_s_ = std::numeric_limits<double>::quiet_NaN();  // for the observer
  std::vector<double> step_force_n_;  // per muscle, this physics step's pull (sensors)
  std::vector<std::array<double, 3>> hold_pos_;
  std::vector<char> held_;
  std::vector<char> fired_;
  std::vector<double> event_time_s_, event_position_;
  bool controller_enabled_ = true;
  std::string end_message_;

  // the observer is shown the state when it asks; without one a step costs one compare
  double next_observation_s_ = std::numeric_limits<double>::infinity();
  // the loop: steps taken, of n_steps_; a control tick every control_every_ steps
  long step_ = 0;
  long n_steps_ = 0;
  long control_every_ = 1;
  // The time after `steps` steps, as the log and the metrics give it: steps / (steps per
  // second) when a second is a whole number of steps (1150 steps of 1 ms are 1.15 s, not
  // 1.1500000000000001), else steps x timestep. MuJoCo's own clock (d->time) adds the step
  // up and drifts (1.168999999999982); the physics does not read these times.
  double time_at(long steps) const;
  long steps_per_second_ = 0;  // 0: a second is no whole number of steps
  bool ended_ = false;
  std::chrono::steady_clock::time_point wall_start_;
  const std::vector<double>* external_pa_ = nullptr;
  std::chrono::steady_clock::duration observer_wall_{};
};

}  // namespace pamsim
