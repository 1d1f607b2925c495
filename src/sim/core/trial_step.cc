// trial_step.cc: the phases of one physics step of a TrialRun (trial_run.h): events and
// holds before the step, sensing, control and the log row at a control tick, MuJoCo and the
// pneumatics, condition events and step-wise metrics after it, and the observer.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "base/units.h"
#include "sim/core/pam_callback.h"
#include "sim/core/trial_run.h"

namespace pamsim {
namespace {

constexpr double kTimeToleranceS = 1e-12;  // a step at t counts as reaching at_s

// Why the step went unstable, or nullptr (no allocation: called at every physics step).
const char* diverged_reason(const mjData* d) {
  if (d->warning[mjWARN_BADQACC].number > 0) return "MuJoCo: bad acceleration (unstable)";
  if (d->warning[mjWARN_BADQVEL].number > 0) return "MuJoCo: bad velocity (unstable)";
  if (d->warning[mjWARN_BADQPOS].number > 0) return "MuJoCo: bad position (unstable)";
  return nullptr;
}

}  // namespace

void TrialRun::hold_bodies() {
  for (std::size_t h = 0; h < held_.size(); ++h) {
    if (!held_[h]) continue;
    const BoundHold& b = tm_.holds[h];
    double* q = d_->qpos + b.qpos;
    q[0] = hold_pos_[h][0];
    q[1] = hold_pos_[h][1];
    q[2] = hold_pos_[h][2];
    q[3] = 1.0;
    q[4] = q[5] = q[6] = 0.0;
    for (int k = 0; k < 6; ++k) d_->qvel[b.dof + k] = 0.0;
  }
}

void TrialRun::fire(std::size_t k, double t) {
  const EventSpec& e = sc_.events[k];
  const BoundEvent& b = tm_.events[k];
  fired_[k] = 1;
  event_time_s_[k] = t;
  event_position_[k] = joint_position();
  switch (e.action) {
    case EventAction::kRelease:
      held_[b.hold] = 0;
      break;
    case EventAction::kAddMass:
      set_body_mass(mutable_model_, b.body, m_->body_mass[b.body] + e.mass_kg);
      break;
    case EventAction::kControllerOff:
      controller_enabled_ = false;
      break;
    case EventAction::kControllerOn:
      controller_enabled_ = true;
      break;
    case EventAction::kEnd:
      end_message_ = "ended by event " + e.name;
      break;
    case EventAction::kSet:
      retune_controller(*e.controller);
      break;
    case EventAction::kMark:
      break;
  }
}

bool TrialRun::fire_now(std::size_t event) {
  if (fired_[event] || ended()) return false;
  fire(event, time_at(step_));
  return true;
}

bool TrialRun::before_step(double t) {
  // events at their time, once what they wait for has happened
  for (std::size_t k = 0; k < sc_.events.size(); ++k) {
    const BoundEvent& b = tm_.events[k];
    if (fired_[k] || sc_.events[k].when.kind != ConditionKind::kTime) continue;
    if (b.after >= 0 && !fired_[b.after]) continue;
    if (t >= sc_.events[k].when.at_s - kTimeToleranceS) fire(k, time_at(step_));
  }
  hold_bodies();
  return end_message_.empty();
}

bool TrialRun::condition_holds(std::size_t k) const {
  const ConditionSpec& c = sc_.events[k].when;
  const BoundEvent& b = tm_.events[k];
  switch (c.kind) {
    case ConditionKind::kContact:
      for (int i = 0; i < d_->ncon; ++i) {
        const int b1 = m_->geom_bodyid[d_->contact[i].geom1];
        const int b2 = m_->geom_bodyid[d_->contact[i].geom2];
        if ((b1 == b.body_a && b2 == b.body_b) || (b1 == b.body_b && b2 == b.body_a)) return true;
      }
      return false;
    case ConditionKind::kJointBelow:
      return d_->qpos[b.joint_qpos] < c.threshold;
    case ConditionKind::kJointAbove:
      return d_->qpos[b.joint_qpos] > c.threshold;
    case ConditionKind::kBodyBelow:
      return d_->xpos[3 * b.body_a + 2] < c.threshold;
    case ConditionKind::kTime:
      return false;
  }
  return false;
}

bool TrialRun::after_step() {
  // events whose condition now holds; step-wise metrics (the time once per step)
  const double now = time_at(step_);
  for (std::size_t k = 0; k < sc_.events.size(); ++k) {
    const int after = tm_.events[k].after;
    if (fired_[k] || (after >= 0 && !fired_[after])) continue;
    if (condition_holds(k)) fire(k, now);
  }
  for (MetricSet* set : step_metrics_) {
    set->on_step(now, joint_position(), event_time_s_);
    set->on_state(d_);
  }
  if (d_->time >= next_observation_s_) show_observer();
  return end_message_.empty();
}

bool TrialRun::control_tick(double t) {
  // the plant as ideal sensors would see it, then what the real ones read
  for (std::size_t i = 0; i < n_; ++i) {
    const int act = tm_.muscles[i].actuator;
    truth_[i].pressure_pa = pneumatics_.pressure_pa(static_cast<int>(i));
    truth_[i].force_n = -pam_actuator_force(m_, d_, act);
    truth_[i].length_m = pam_muscle_length(m_, d_, act, &muscle_[i].free_length);
    p_tp_pa_[i] = sc_.muscles[tm_.muscles[i].spec].command.at(t);
  }
  sensors_.sample(truth_, &readings_);

  // new valve commands; an absurd gain can drive them out of range (e.g. to infinity)
  ControlInput in;
  in.time_s = t;
  in.enabled = controller_enabled_;
  in.readings = &readings_;
  in.p_tp_pa = &p_tp_pa_;
  try {
    controller_->update(in, &out_);
    if (std::isnan(first_trigger_s_) && first_window_open()) {
      first_trigger_s_ = time_at(step_);  // recorded: the exact decimal time
    }
    if (options_.command_source && !source_command(t)) return false;
    const std::vector<double>& p_cmd = options_.command_source ? source_pa_
                                       : external_pa_          ? *external_pa_
                                                               : out_.p_cmd_pa;
    for (std::size_t i = 0; i < n_; ++i) pneumatics_.set_command(static_cast<int>(i), p_cmd[i]);
    if (options_.control_log) log_control(t);
  } catch (const std::exception& e) {
    set_status("diverged", std::string("controller: ") + e.what(), t);
    return false;
  }
  log_row(time_at(step_));
  return true;
}

bool TrialRun::source_command(double t) {
  ControlTick tick;
  tick.index = step_ / control_every_;
  tick.time_s = time_at(step_);
  tick.enabled = controller_enabled_;
  tick.readings = &readings_;
  tick.p_tp_pa = &p_tp_pa_;
  tick.controller_pa = &out_.p_cmd_pa;
  source_pa_ = out_.p_cmd_pa;
  std::string why;
  if (options_.command_source->command(tick, &source_pa_, &why)) return true;
  set_status("link_lost", why, t);
  return false;
}

bool TrialRun::first_window_open() const {
  // the controller's first window channel (a reflex's Ia windows), any muscle
  for (std::size_t k = 0; k < channels_.size(); ++k) {
    if (!channels_[k].window) continue;
    const std::vector<double>& open = out_.channels[k];
    return std::any_of(open.begin(), open.end(), [](double v) { return v != 0.0; });
  }
  return false;
}

void TrialRun::log_control(double t) {
  // the embedded controller's inputs as the controller was handed them, and its commands
  ControlLog& log = *options_.control_log;
  log.muscle_count = static_cast<int>(n_);
  log.values.push_back(t);
  log.values.push_back(controller_enabled_ ? 1.0 : 0.0);
  for (std::size_t i = 0; i < n_; ++i) {
    const MuscleReading& r = readings_[i];
    log.values.insert(log.values.end(), {r.pressure_sensor_v, r.gauge_v, r.fiber_rate_m_s,
                                         p_tp_pa_[i], out_.p_cmd_pa[i]});
  }
}

void TrialRun::log_row(double t) {
  // the state at this tick as the channel table reads it (trial_channels.h)
  TrialObservation& o = tick_;
  o.time_s = t;
  o.steps = step_;
  o.joint_position_rad_or_m = joint_position();
  o.joint_velocity_rad_or_m_per_s = d_->qvel[tm_.joint.dof];
  for (std::size_t h = 0; h < tm_.holds.size(); ++h) {
    o.body_z_m[h] = d_->qpos[tm_.holds[h].qpos + 2];
  }
  for (std::size_t i = 0; i < n_; ++i) {
    o.command_pa[i] = pneumatics_.command_pa(static_cast<int>(i));
    o.pressure_pa[i] = truth_[i].pressure_pa;
    o.force_n[i] = truth_[i].force_n;
    o.length_m[i] = truth_[i].length_m;
    o.length_est_m[i] = readings_[i].length_est_m;
    o.velocity_est_m_s[i] = out_.velocity_m_s[i];
  }
  o.readings = readings_;
  o.channels = out_.channels;
  write_log_row(layout_, o, row_.data());
  result_.trajectory.values.insert(result_.trajectory.values.end(), row_.begin(), row_.end());
}

bool TrialRun::physics_step(double t) {
  // forces with the pressures at t
  mj_step2(m_, d_);
  const char* unstable = diverged_reason(d_);
  if (!unstable && !std::isfinite(joint_position())) unstable = "non-finite joint position";
  if (unstable) {
    set_status("diverged", unstable, t);
    return false;
  }
  // an instrument that follows the pull between ticks sees this step's (a ringing board):
  // the lines' pulls at t, which MuJoCo has just applied (the board takes its pull as linear
  // from the last step's to this one, board_vibration.h)
  for (std::size_t i = 0; i < n_; ++i) {
    step_force_n_[i] = -d_->actuator_force[tm_.muscles[i].actuator];
    // a NaN pull sticks, as the sensors' extremes do: a diverged trial reports no peak
    double& peak = muscle_[i].peak_tension_n;
    if (!std::isnan(peak) && !(step_force_n_[i] <= peak)) peak = step_force_n_[i];
  }
  if (sensors_.observes_forces()) sensors_.observe(step_force_n_);

  // pneumatics over [t, t + dt] with this step's muscle length and velocity: the line's
  // while it is taut; a slack muscle rests at its free length, which moves with its
  // pressure (the length's rate over the last step). The muscle's history (a Maxwell-slip
  // friction's elements, the bladder's relaxation) moves to that length now, after every
  // force of the step was computed.
  try {
    for (std::size_t i = 0; i < n_; ++i) {
      const int act = tm_.muscles[i].actuator;
      const double taut = pam_taut_length_committing_creep(m_, d_, act, sc_.timestep_s);
      MuscleLoopState& muscle = muscle_[i];
      const double length = pam_muscle_length_at(m_, d_, act, taut, &muscle.free_length);
      // (an extensible line's stretch moves the muscle apart from the tendon: its length's
      // rate too)
      const bool slack = taut<length, stretches = pam_line_axial_stiffness(m_, act)> 0.0;
      const double velocity = slack || stretches ? (length - muscle.length_m) / sc_.timestep_s
                                                 : d_->actuator_velocity[act];
      muscle.length_m = length;
      if (muscle.has_history) pam_commit_history(m_, d_, act, length);
      pneumatics_.set_kinematics(static_cast<int>(i), length, velocity);
    }
    pneumatics_.advance(t + sc_.timestep_s);
  } catch (const std::exception& e) {
    set_status("diverged", std::string("pneumatics: ") + e.what(), t);
    return false;
  }
  for (std::size_t i = 0; i < n_; ++i) {
    d_->userdata[tm_.muscles[i].pressure_slot] = pneumatics_.pressure_pa(static_cast<int>(i));
  }
  return true;
}

void TrialRun::set_status(const std::string& status, const std::string& why, double t) {
  result_.summary.status = status;
  result_.summary.message = why + " at t = " + std::to_string(t) + " s";
}

TrialSnapshot TrialRun::snapshot() {
  for (std::size_t i = 0; i < n_; ++i) {
    pressure_pa_[i] = pneumatics_.pressure_pa(static_cast<int>(i));
    command_pa_[i] = pneumatics_.command_pa(static_cast<int>(i));
  }
  TrialSnapshot snapshot;
  snapshot.model = m_;
  snapshot.data = d_;
  snapshot.time_s = time_at(step_);
  snapshot.hinge = tm_.joint.hinge;
  snapshot.joint_position_deg_or_mm =
      tm_.joint.hinge ? units::rad_to_deg(joint_position()) : units::m_to_mm(joint_position());
  snapshot.labels = &labels_;
  snapshot.pressure_pa = &pressure_pa_;
  snapshot.command_pa = &command_pa_;
  snapshot.channels = &channels_;
  snapshot.channel_values = &out_.channels;
  snapshot.first_trigger_s = first_trigger_s_;
  return snapshot;
}

void TrialRun::show_observer() {
  const auto start = std::chrono::steady_clock::now();
  options_.observer->observe(snapshot());
  next_observation_s_ = options_.observer->next_observation_time_s() - kObservationToleranceS;
  observer_wall_ += std::chrono::steady_clock::now() - start;
}

}  // namespace pamsim
