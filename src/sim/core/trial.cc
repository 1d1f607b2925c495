// trial.cc: see trial.h.
#include "sim/core/trial.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "pam_actuator/pneumatics.h"
#include "pam_actuator/units.h"
#include "reflex/sensing.h"
#include "sim/core/pam_callback.h"

namespace pamsim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kTimeToleranceS = 1e-12;   // a step at t counts as reaching at_s

// Why the step went unstable, or nullptr (no allocation: called at every physics step).
const char* diverged_reason(const mjData* d) {
  if (d->warning[mjWARN_BADQACC].number > 0) return "MuJoCo: bad acceleration (unstable)";
  if (d->warning[mjWARN_BADQVEL].number > 0) return "MuJoCo: bad velocity (unstable)";
  if (d->warning[mjWARN_BADQPOS].number > 0) return "MuJoCo: bad position (unstable)";
  return nullptr;
}

std::vector<BraidGeometry> braids_of(const TrialModel& tm) {
  std::vector<BraidGeometry> braid;
  for (const BoundMuscle& b : tm.muscles) braid.push_back(b.braid);
  return braid;
}

std::vector<double> start_commands(const TrialModel& tm, const Scenario& sc) {
  std::vector<double> p0;
  for (const BoundMuscle& b : tm.muscles) p0.push_back(sc.muscles[b.spec].command.at(0.0));
  return p0;
}

std::vector<MuscleSensorSpec> sensor_specs(const TrialModel& tm, const Scenario& sc) {
  std::vector<MuscleSensorSpec> specs;
  for (const BoundMuscle& b : tm.muscles) {
    const MuscleSpec& spec = sc.muscles[b.spec];
    specs.push_back({spec.key, spec.pam.spring, *spec.pam.strain_gauge});
  }
  return specs;
}

std::unique_ptr<Controller> make_controller(const TrialModel& tm, const Scenario& sc) {
  if (sc.controller == ControllerKind::kNone) return std::make_unique<PassThroughController>();
  StretchReflexControllerConfig config = sc.reflex;
  config.muscle_count = static_cast<int>(tm.muscles.size());
  config.pairs = tm.pairs;
  config.control_hz = sc.control_hz;
  return std::make_unique<StretchReflexController>(config);
}

std::vector<std::string> held_bodies(const TrialModel& tm) {
  std::vector<std::string> names;
  for (const BoundHold& h : tm.holds) names.push_back(mj_id2name(tm.model.get(), mjOBJ_BODY, h.body));
  return names;
}

std::vector<std::string> labels_of(const TrialModel& tm) {
  std::vector<std::string> labels;
  for (const BoundMuscle& b : tm.muscles) labels.push_back(b.label);
  return labels;
}

// One trial from start to summary; each method is one phase of a physics step.
class TrialRun {
 public:
  TrialRun(const TrialModel& tm, const Scenario& sc, std::uint64_t seed, const TrialOptions& opt);
  TrialResult run();

 private:
  void start_state();
  bool before_step(double t);    // false: an event ended the trial
  bool control_tick(double t);   // false: the controller failed (diverged)
  bool physics_step(double t);   // false: the step diverged
  bool after_step();             // false: an event ended the trial
  void fire(std::size_t k, double t);
  bool condition_holds(std::size_t k) const;
  void hold_bodies();
  void log_row(double t);
  void show_observer();
  double joint_position() const { return d_->qpos[tm_.joint.qpos]; }
  void set_status(const std::string& status, const std::string& why, double t);
  TrialSummary finish(long steps, std::chrono::steady_clock::duration wall);

  const TrialModel& tm_;
  const Scenario& sc_;
  const TrialOptions& options_;
  MjModelPtr own_model_;   // a copy, only when events change the model
  mjModel* mutable_model_ = nullptr;
  const mjModel* m_;
  MjDataPtr data_;
  mjData* d_;
  const std::size_t n_;    // muscles
  const std::vector<std::string> labels_;
  const std::vector<double> start_p_pa_;   // the schedules at t = 0
  PneumaticSystem pneumatics_;
  SensorSuite sensors_;
  std::unique_ptr<Controller> controller_;
  std::vector<std::unique_ptr<MetricSet>> metrics_;
  std::vector<MetricSet*> step_metrics_;
  LogLayout layout_;
  TrialResult result_;

  // per tick and per step state, allocated once
  std::vector<MuscleTruth> truth_;
  std::vector<MuscleReading> readings_;
  std::vector<double> p_tp_pa_;
  ControlOutput out_;
  std::vector<double> row_;
  std::vector<double> pressure_pa_, command_pa_;
  std::vector<std::array<double, 3>> hold_pos_;
  std::vector<char> held_;
  std::vector<char> fired_;
  std::vector<double> event_time_s_, event_position_;
  bool controller_enabled_ = true;
  std::string end_message_;

  // the observer is shown the state when it asks; without one a step costs one compare
  double next_observation_s_ = kInfinity;
  std::chrono::steady_clock::duration observer_wall_{};
};

TrialRun::TrialRun(const TrialModel& tm, const Scenario& sc, std::uint64_t seed,
                   const TrialOptions& opt)
    : tm_(tm),
      sc_(sc),
      options_(opt),
      own_model_(tm.events_change_model ? MjModelPtr(mj_copyModel(nullptr, tm.model.get()))
                                        : nullptr),
      mutable_model_(own_model_.get()),
      m_(own_model_ ? own_model_.get() : tm.model.get()),
      data_(make_data(m_)),
      d_(data_.get()),
      n_(tm.muscles.size()),
      labels_(labels_of(tm)),
      start_p_pa_(start_commands(tm, sc)),
      pneumatics_(sc.pneumatics, sc.valve_model, braids_of(tm), start_p_pa_, 0.0),
      sensors_(sc.sensing, sensor_specs(tm, sc), seed),
      controller_(make_controller(tm, sc)),
      metrics_(make_metric_sets(sc)),
      layout_(make_log_layout(tm.joint.hinge, held_bodies(tm), labels_,
                              sc.controller == ControllerKind::kStretchReflex)) {
  if (m_->opt.timestep != sc.timestep_s) {
    throw std::logic_error("run_trial: the model's timestep differs from sim.timestep_s "
                           "(load it with load_trial_model)");
  }
  for (const auto& set : metrics_) {
    if (set->wants_steps()) step_metrics_.push_back(set.get());
  }
  result_.summary.seed = seed;
  result_.trajectory.columns = layout_.columns;
  truth_.resize(n_);
  readings_.resize(n_);
  p_tp_pa_.resize(n_);
  out_.resize(static_cast<int>(n_));
  row_.resize(layout_.columns.size());
  pressure_pa_.resize(n_);
  command_pa_.resize(n_);
  held_.assign(tm.holds.size(), 1);
  fired_.assign(sc.events.size(), 0);
  event_time_s_.assign(sc.events.size(), kNaN);
  event_position_.assign(sc.events.size(), kNaN);
}

void TrialRun::start_state() {
  // at rest at the start position; held bodies wait in place
  if (sc_.has_start_position) d_->qpos[tm_.joint.qpos] = sc_.start_position;
  mj_forward(m_, d_);
  for (std::size_t h = 0; h < tm_.holds.size(); ++h) {
    const BoundHold& b = tm_.holds[h];
    const HoldSpec& spec = sc_.holds[h];
    std::array<double, 3> pos = spec.position_m;
    if (!spec.at_position) {
      const double* site = d_->site_xpos + 3 * b.site;
      pos = {site[0], site[1], site[2] + spec.height_m + b.radius_m};
    }
    hold_pos_.push_back(pos);
  }
  hold_bodies();

  // pneumatics start at the scheduled pressures, in equilibrium
  for (std::size_t i = 0; i < n_; ++i) {
    pneumatics_.set_command(static_cast<int>(i), start_p_pa_[i]);
    d_->userdata[i] = pneumatics_.pressure_pa(static_cast<int>(i));
  }
}

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
    case EventAction::kRelease: held_[b.hold] = 0; break;
    case EventAction::kAddMass: set_body_mass(mutable_model_, b.body, m_->body_mass[b.body] + e.mass_kg); break;
    case EventAction::kControllerOff: controller_enabled_ = false; break;
    case EventAction::kControllerOn: controller_enabled_ = true; break;
    case EventAction::kEnd: end_message_ = "ended by event " + e.name; break;
    case EventAction::kMark: break;
  }
}

bool TrialRun::before_step(double t) {
  // events at their time, once what they wait for has happened
  for (std::size_t k = 0; k < sc_.events.size(); ++k) {
    const BoundEvent& b = tm_.events[k];
    if (fired_[k] || sc_.events[k].when.kind != ConditionKind::kTime) continue;
    if (b.after >= 0 && !fired_[b.after]) continue;
    if (t >= sc_.events[k].when.at_s - kTimeToleranceS) fire(k, t);
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
    case ConditionKind::kJointBelow: return d_->qpos[b.joint_qpos] < c.threshold;
    case ConditionKind::kJointAbove: return d_->qpos[b.joint_qpos] > c.threshold;
    case ConditionKind::kBodyBelow: return d_->xpos[3 * b.body_a + 2] < c.threshold;
    case ConditionKind::kTime: return false;
  }
  return false;
}

bool TrialRun::after_step() {
  // events whose condition now holds; step-wise metrics
  for (std::size_t k = 0; k < sc_.events.size(); ++k) {
    const int after = tm_.events[k].after;
    if (fired_[k] || (after >= 0 && !fired_[after])) continue;
    if (condition_holds(k)) fire(k, d_->time);
  }
  for (MetricSet* set : step_metrics_) set->on_step(d_->time, joint_position(), event_time_s_);
  if (d_->time >= next_observation_s_) show_observer();
  return end_message_.empty();
}

bool TrialRun::control_tick(double t) {
  // the plant as ideal sensors would see it, then what the real ones read
  for (std::size_t i = 0; i < n_; ++i) {
    const int act = tm_.muscles[i].actuator;
    truth_[i].pressure_pa = pneumatics_.pressure_pa(static_cast<int>(i));
    truth_[i].force_n = -pam_actuator_force(m_, d_, act);
    truth_[i].length_m = pam_length(m_, d_, act);
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
    for (std::size_t i = 0; i < n_; ++i) pneumatics_.set_command(static_cast<int>(i), out_.p_cmd_pa[i]);
  } catch (const std::exception& e) {
    set_status("diverged", std::string("controller: ") + e.what(), t);
    return false;
  }
  log_row(t);
  return true;
}

void TrialRun::log_row(double t) {
  // the joint in deg (hinge) or mm (slide), held bodies' heights, then every muscle
  const double q = joint_position(), qdot = d_->qvel[tm_.joint.dof];
  row_[layout_.time] = t;
  row_[layout_.joint_position] = tm_.joint.hinge ? units::rad_to_deg(q) : units::m_to_mm(q);
  row_[layout_.joint_velocity] = tm_.joint.hinge ? units::rad_to_deg(qdot) : units::m_to_mm(qdot);
  for (std::size_t h = 0; h < tm_.holds.size(); ++h) {
    row_[layout_.body_z[h]] = d_->qpos[tm_.holds[h].qpos + 2];
  }
  for (std::size_t i = 0; i < n_; ++i) {
    const MuscleColumns& c = layout_.muscle[i];
    const MuscleReading& r = readings_[i];
    row_[c.p_cmd] = units::pa_to_mpa(pneumatics_.command_pa(static_cast<int>(i)));
    row_[c.p] = units::pa_to_mpa(truth_[i].pressure_pa);
    row_[c.force] = truth_[i].force_n;
    row_[c.length] = units::m_to_mm(truth_[i].length_m);
    row_[c.length_est] = units::m_to_mm(r.length_est_m);
    row_[c.velocity_est] = units::m_to_mm(out_.velocity_m_s[i]);
    if (c.reflex != kNoColumn) row_[c.reflex] = out_.reflex_active[i] ? 1.0 : 0.0;
    row_[c.pressure_sensor] = r.pressure_sensor_v;
    row_[c.gauge] = r.gauge_v;
    row_[c.fiber_rate] = units::m_to_mm(r.fiber_rate_m_s);
    row_[c.p_meas] = units::pa_to_mpa(r.pressure_meas_pa);
    row_[c.force_meas] = r.force_meas_n;
  }
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

  // pneumatics over [t, t + dt] with this step's PAM length and velocity
  try {
    for (std::size_t i = 0; i < n_; ++i) {
      const int act = tm_.muscles[i].actuator;
      pneumatics_.set_kinematics(static_cast<int>(i), pam_length(m_, d_, act),
                                 d_->actuator_velocity[act]);
    }
    pneumatics_.advance(t + sc_.timestep_s);
  } catch (const std::exception& e) {
    set_status("diverged", std::string("pneumatics: ") + e.what(), t);
    return false;
  }
  for (std::size_t i = 0; i < n_; ++i) d_->userdata[i] = pneumatics_.pressure_pa(static_cast<int>(i));
  return true;
}

void TrialRun::set_status(const std::string& status, const std::string& why, double t) {
  result_.summary.status = status;
  result_.summary.message = why + " at t = " + std::to_string(t) + " s";
}

void TrialRun::show_observer() {
  const auto start = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < n_; ++i) {
    pressure_pa_[i] = pneumatics_.pressure_pa(static_cast<int>(i));
    command_pa_[i] = pneumatics_.command_pa(static_cast<int>(i));
  }
  TrialSnapshot snapshot;
  snapshot.model = m_;
  snapshot.data = d_;
  snapshot.time_s = d_->time;
  snapshot.hinge = tm_.joint.hinge;
  snapshot.joint_position = tm_.joint.hinge ? units::rad_to_deg(joint_position())
                                            : units::m_to_mm(joint_position());
  snapshot.labels = &labels_;
  snapshot.pressure_pa = &pressure_pa_;
  snapshot.command_pa = &command_pa_;
  snapshot.reflex_active = &out_.reflex_active;
  options_.observer->observe(snapshot);
  next_observation_s_ = options_.observer->next_observation_time_s() - kObservationToleranceS;
  observer_wall_ += std::chrono::steady_clock::now() - start;
}

TrialSummary TrialRun::finish(long steps, std::chrono::steady_clock::duration wall) {
  FinishedTrial record;
  record.scenario = &sc_;
  record.log = &result_.trajectory;
  record.layout = &layout_;
  record.labels = labels_;
  record.hinge = tm_.joint.hinge;
  record.event_time_s = event_time_s_;
  record.event_position = event_position_;
  record.trigger_times_s = controller_->trigger_times_s();
  record.steps = steps;
  record.sim_time_s = steps * sc_.timestep_s;
  record.wall_time_s = std::chrono::duration<double>(wall - observer_wall_).count();
  record.cvode_steps = pneumatics_.steps();
  record.cvode_rhs_evals = pneumatics_.rhs_evals();
  TrialSummary& s = result_.summary;
  for (const auto& set : metrics_) set->finish(record, &s.metrics);
  if (s.status == "ok" && !end_message_.empty()) s.message = end_message_;
  return s;
}

TrialResult TrialRun::run() {
  start_state();
  const long n_steps = std::lround(sc_.duration_s / sc_.timestep_s);
  const long control_every = std::lround(1.0 / (sc_.control_hz * sc_.timestep_s));
  result_.trajectory.values.reserve((n_steps / control_every + 1) * layout_.columns.size());

  const auto wall_start = std::chrono::steady_clock::now();
  if (options_.observer) {
    next_observation_s_ = options_.observer->next_observation_time_s() - kObservationToleranceS;
    if (d_->time >= next_observation_s_) show_observer();
  }
  long step = 0;
  for (; step < n_steps; ++step) {
    const double t = step * sc_.timestep_s;
    if (!before_step(t)) break;
    mj_step1(m_, d_);
    if (step % control_every == 0 && !control_tick(t)) break;
    if (!physics_step(t)) {
      ++step;
      break;
    }
    if (!after_step()) {
      ++step;
      break;
    }
  }
  const auto wall = std::chrono::steady_clock::now() - wall_start;
  finish(step, wall);
  if (!options_.keep_trajectory) result_.trajectory.values.clear();
  return std::move(result_);
}

}  // namespace

TrialResult run_trial(const TrialModel& model, const Scenario& scenario, std::uint64_t seed,
                      const TrialOptions& options) {
  TrialRun trial(model, scenario, seed, options);
  return trial.run();
}

}  // namespace pamsim
