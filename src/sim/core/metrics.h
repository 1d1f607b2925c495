// metrics.h: a trial's summary, made by small metric sets that each experiment lists
// (the scenario's `metrics` key; the sets and their metrics are listed at metric_set_names),
// followed by the sets every trial has (trial, solver). A metric is NaN where it is
// undefined (an event that did not happen); JSON writes null.
#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "reflex/controller.h"
#include "sim/core/scenario.h"
#include "sim/core/trial_log.h"

namespace pamsim {

struct Metric {
  std::string name;
  double value = 0.0;
  bool integer = false;  // a count (written as an integer)
};

struct TrialSummary {
  std::string status = "ok";  // "ok" | "diverged" | "failed" (a sweep trial that could not run)
                              // | "link_lost" (`pamsim hil`: the controller went silent)
  std::string message;        // why, when not ok; or which event ended the trial
  std::uint64_t seed = 0;
  std::vector<Metric> metrics;

  // The metric's value, NaN if the summary has no such metric.
  double metric(const std::string& name) const;
};

// Timing metrics (wall_time_s, realtime_factor) vary from run to run.
bool is_timing_metric(const std::string& name);

// What the metric sets see of a finished trial.
struct FinishedTrial {
  const Scenario* scenario = nullptr;
  const Trajectory* log = nullptr;
  const LogLayout* layout = nullptr;
  std::vector<std::string> labels;       // muscles, model order
  bool hinge = true;                     // the joint's kind
  std::vector<double> event_time_s;      // per Scenario::events, NaN if it never fired
  std::vector<double> event_position;    // the joint's position when it fired [rad or m]
  std::vector<char> event_holds_at_end;  // per event: its condition holds in the final state
  // the events the controller recorded: their kinds, and their times [event][muscle][k]
  const std::vector<ControllerEvent>* events = nullptr;
  const std::vector<std::vector<std::vector<double>>>* event_times_s = nullptr;
  std::vector<double> peak_tension_n;  // per muscle, the largest pull of a physics step
  long steps = 0;
  double sim_time_s = 0.0;
  double wall_time_s = 0.0;
  long cvode_steps = 0;
  long cvode_rhs_evals = 0;
  // The times per muscle of the controller's event `name`, nullptr if it records none.
  const std::vector<std::vector<double>>* controller_event(const std::string& name) const;
};

class MetricSet {
 public:
  virtual ~MetricSet() = default;
  // Sets that follow the trial step by step say so; they are shown the joint's position
  // [rad or m] after every physics step, with the events' times so far.
  virtual bool wants_steps() const { return false; }
  virtual void on_step(double /*time_s*/, double /*joint_position*/,
                       const std::vector<double>& /*event_time_s*/) {}
  // ... and the trial's MuJoCo data after every physics step (read only).
  virtual void on_state(const mjData* /*d*/) {}
  // Appends the set's metrics, always the same names in the same order.
  virtual void finish(const FinishedTrial& record, std::vector<Metric>* out) const = 0;
};

// The names a scenario may list, in the documented order, and what each set gives:
//   drop              the falling mass: start_angle_deg (at the "release" event),
//                     min_angle_deg and min_angle_time_s (every physics step after it),
//                     peak_drop_deg = start - min, final_angle_deg, impact_time_s (the
//                     "impact" event), recovery_time_s (impact until the angle stays within
//                     2 deg of its final value), mass_retained (1 if the impact's two
//                     bodies, the mass and the basket, still touch at the end, else 0);
//                     needs a hinge joint and both events
//   reflex            reflex_triggers_<m> per muscle, first_trigger_time_s, mistrips
//                     (triggers before the "impact" event, or all if there is none),
//                     retriggers_after_impact (triggers from the impact on, all muscles,
//                     beyond the first)
//   length_estimate   length_est_rmse_mm, length_est_max_error_mm, and the same in % of the
//                     true length (length_est_rmse_pct, length_est_max_error_pct): the
//                     model-based length estimate against the encoder, all muscles, every
//                     tick (Table III's and Table V's metric)
//   tracking          per muscle: pressure_rmse_<m>_MPa (chamber vs command),
//                     length_est_rmse_<m>_pct, length_est_max_error_<m>_pct (in % of the
//                     true length, Table III's metric); the joint's start, final, min and
//                     max (angle_*_deg or position_*_mm)
//   sensors           the extremes of every named MJCF sensor over every physics step, and
//                     a touch sensor's touchdowns (sensor_metrics.h)
//   events            event_<name>_time_s: when each scenario event fired, NaN if never
//   tension           per muscle: peak_tension_<m>_N (the line's largest pull over every
//                     physics step), line_load_<m>_pct (that in per cent of its
//                     muscles.<m>.line_limit_N, where given), line_break_load_<m>_pct (in per
//                     cent of its break load, where muscles.<m>.line_strength_MPa is given:
//                     over 100 the line breaks) and tension_triggers_<m> (its
//                     tension (Ib) reflex's triggers; 0 without one);
//                     first_tension_trigger_time_s
//   (always) trial    steps, sim_time_s, wall_time_s, realtime_factor
//   (always) solver   cvode_steps, cvode_rhs_evals
const std::vector<std::string>& metric_set_names();

// The sets of a scenario: its `metrics` list, then trial and solver. Throws InputError
// "<scenario>: metrics ..." for an unknown name or a set whose events are missing. The
// "sensors" set reads `model`'s sensors (none for a null model: a scenario checked alone).
std::vector<std::unique_ptr<MetricSet>> make_metric_sets(const Scenario& scenario,
                                                         const mjModel* model = nullptr);

// Throws InputError "<scenario>: metrics name two metrics <name> ..." if a name repeats (a
// model's sensor named like another set's metric: "angle" gives angle_min_deg, as tracking).
void require_unique_metric_names(const Scenario& scenario, std::vector<std::string> names);

// The metric names a scenario's summaries hold on its trial model, in order (a sweep
// database's columns).
std::vector<std::string> metric_names(const Scenario& scenario,
                                      const std::vector<std::string>& labels, bool hinge,
                                      const mjModel* model);

}  // namespace pamsim
