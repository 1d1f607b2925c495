// trial.cc: see trial.h. Sets up a TrialRun (trial_run.h) and runs it; the phases of a
// step are in trial_step.cc.
#include "sim/core/trial.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include "base/input_error.h"
#include "base/no_value.h"
#include "base/units.h"
#include "reflex/pass_through_controller.h"
#include "sim/core/pam_callback.h"
#include "sim/core/trial_run.h"

namespace pamsim {
namespace {

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
    specs.push_back({spec.key, spec.pam.spring, *spec.pam.strain_gauge, spec.gauge_contact});
  }
  return specs;
}

// the scenario's controller for the bound model: its muscles, pairs and control rate are
// given here, and only here

std::unique_ptr<Controller> make_controller(const TrialModel& tm, const Scenario& sc) {
  if (!sc.controller) {
    return std::make_unique<PassThroughController>(static_cast<int>(tm.muscles.size()));
  }
  return sc.controller->make_controller(controller_setup(tm, sc));
}

std::vector<std::string> held_bodies(const TrialModel& tm) {
  std::vector<std::string> names;
  for (const BoundHold& h : tm.holds)
    names.push_back(mj_id2name(tm.model.get(), mjOBJ_BODY, h.body));
  return names;
}

std::vector<std::string> labels_of(const TrialModel& tm) {
  std::vector<std::string> labels;
  for (const BoundMuscle& b : tm.muscles) labels.push_back(b.label);
  return labels;
}

// the data this thread lends to trials on one model
struct ThreadTrialData {
  std::uint64_t model_id = 0;
  MjDataPtr data;
  bool lent = false;
};
thread_local ThreadTrialData t_trial_data;

}  // namespace

LogLayout trial_log_layout(const TrialModel& tm, const Scenario& sc) {
  return make_log_layout(tm.joint.hinge, held_bodies(tm), labels_of(tm), sc.controller_channels());
}

TrialData::TrialData(const TrialModel& model, const mjModel* m, bool stays_on_thread) {
  ThreadTrialData& cache = t_trial_data;
  const bool shared_model = m == model.model.get();
  if (!shared_model || cache.lent || !stays_on_thread) {
    own_ = make_data(m);
    d_ = own_.get();
    return;
  }
  if (cache.model_id != model.id || !cache.data) {
    cache.data = make_data(m);
    cache.model_id = model.id;
  } else {
    mj_resetData(m, cache.data.get());
  }
  cache.lent = true;
  borrowed_ = true;
  d_ = cache.data.get();
}

TrialData::~TrialData() {
  if (borrowed_) t_trial_data.lent = false;
}

std::string embedded_controller_config(const TrialModel& tm, const Scenario& sc,
                                       pamctl_config* config) {
  // the estimators as the sensing builds them (the gauges calibrated), then the controller
  const SensorSuite sensors(sc.sensing, sensor_specs(tm, sc), 0);
  *config = sensors.embedded_config();
  if (!sc.controller) {
    embed_pass_through(controller_setup(tm, sc), config);
    return "";
  }
  return sc.controller->embedded(controller_setup(tm, sc), config);
}

TrialRun::TrialRun(const TrialModel& tm, const Scenario& sc, std::uint64_t seed,
                   const TrialOptions& opt, bool stays_on_thread)
    : tm_(tm),
      sc_(sc),
      options_(opt),
      own_model_(tm.events_change_model ? copy_model(tm.model.get()) : nullptr),
      mutable_model_(own_model_.get()),
      m_(own_model_ ? own_model_.get() : tm.model.get()),
      data_(tm, m_, stays_on_thread),
      d_(data_.get()),
      n_(tm.muscles.size()),
      labels_(labels_of(tm)),
      start_p_pa_(start_commands(tm, sc)),
      pneumatics_(sc.pneumatics, sc.valve_model, braids_of(tm), start_p_pa_, 0.0),
      sensors_(sc.sensing, sensor_specs(tm, sc), seed),
      controller_(make_controller(tm, sc)),
      metrics_(make_metric_sets(sc, m_)),
      layout_(trial_log_layout(tm, sc)),
      channels_(sc.controller_channels()),
      events_(sc.controller_events()) {
  if (m_->opt.timestep != sc.timestep_s) {
    throw std::logic_error(
        "run_trial: the model's timestep differs from sim.timestep_s "
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
  out_.resize(static_cast<int>(n_), static_cast<int>(channels_.size()));
  row_.resize(layout_.columns.size());
  tick_.body_z_m.resize(tm_.holds.size());
  for (auto* v : {&tick_.command_pa, &tick_.pressure_pa, &tick_.force_n, &tick_.length_m,
                  &tick_.length_est_m, &tick_.velocity_est_m_s}) {
    v->resize(n_);
  }
  pressure_pa_.resize(n_);
  command_pa_.resize(n_);
  muscle_.resize(n_);
  step_force_n_.resize(n_);
  for (std::size_t i = 0; i < n_; ++i) {  // a physical muscle's chamber has its own shape
    const MuscleSpec& spec = sc.muscles[tm.muscles[i].spec];
    if (spec.plant_file.empty()) continue;
    pneumatics_.set_plant_volume(static_cast<int>(i), spec.plant);
    muscle_[i].has_history = pam_has_history(spec.plant);
  }
  held_.assign(tm.holds.size(), 1);
  fired_.assign(sc.events.size(), 0);
  event_time_s_.assign(sc.events.size(), kNaN);
  event_position_.assign(sc.events.size(), kNaN);
}

void TrialRun::start_state() {
  // at rest at the start position; held bodies wait in place
  tm_.place_at_start(sc_, d_);
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
    d_->userdata[tm_.muscles[i].pressure_slot] = pneumatics_.pressure_pa(static_cast<int>(i));
    pam_start_line_creep(m_, d_, tm_.muscles[i].actuator);
    muscle_[i].length_m =
        pam_muscle_length(m_, d_, tm_.muscles[i].actuator, &muscle_[i].free_length);
  }
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
  for (std::size_t k = 0; k < sc_.events.size(); ++k) {
    record.event_holds_at_end.push_back(condition_holds(k) ? 1 : 0);
  }
  record.events = &events_;
  record.event_times_s = &controller_->event_times_s();
  for (const MuscleLoopState& muscle : muscle_)
    record.peak_tension_n.push_back(muscle.peak_tension_n);
  record.steps = steps;
  record.sim_time_s = time_at(steps);
  record.wall_time_s = std::chrono::duration<double>(wall - observer_wall_).count();
  record.cvode_steps = pneumatics_.steps();
  record.cvode_rhs_evals = pneumatics_.rhs_evals();
  TrialSummary& s = result_.summary;
  for (const auto& set : metrics_) set->finish(record, &s.metrics);
  if (s.status == "ok" && !end_message_.empty()) s.message = end_message_;
  return s;
}

TrialResult TrialRun::run() {
  begin();
  while (step()) {
  }
  return end();
}

void TrialRun::begin() {
  start_state();
  n_steps_ = std::lround(sc_.duration_s / sc_.timestep_s);
  control_every_ = std::lround(1.0 / (sc_.control_hz * sc_.timestep_s));
  const double per_second = 1.0 / sc_.timestep_s;
  if (std::fabs(per_second - std::round(per_second)) < 1e-9 * per_second) {
    steps_per_second_ = std::lround(per_second);
  }
  result_.trajectory.values.reserve((n_steps_ / control_every_ + 1) * layout_.columns.size());

  wall_start_ = std::chrono::steady_clock::now();
  if (options_.observer) {
    next_observation_s_ = options_.observer->next_observation_time_s() - kObservationToleranceS;
    if (d_->time >= next_observation_s_) show_observer();
  }
}

bool TrialRun::step() {
  if (ended()) return false;
  // the controller's and the events' clock, step times the timestep (the schedules' edges
  // fall on it); what is recorded reads time_at(step_), the exact decimal time
  const double t = step_ * sc_.timestep_s;
  // an event or the controller can end the trial before the step counts; a step that
  // diverges or fires an ending event counts
  bool going = before_step(t);
  if (going) {
    mj_step1(m_, d_);
    going = step_ % control_every_ != 0 || control_tick(t);
  }
  if (going) {
    ++step_;
    going = physics_step(t) && after_step();
  }
  ended_ = !going;
  return going;
}

double TrialRun::time_at(long steps) const {
  if (steps_per_second_ > 0) {
    return static_cast<double>(steps) / static_cast<double>(steps_per_second_);
  }
  return static_cast<double>(steps) * sc_.timestep_s;
}

TrialResult TrialRun::end() {
  const auto wall = std::chrono::steady_clock::now() - wall_start_;
  finish(step_, wall);
  if (!options_.keep_trajectory) result_.trajectory.values.clear();
  return std::move(result_);
}

TrialObservation TrialRun::observe() const {
  TrialObservation o;
  o.time_s = time_at(step_);
  o.steps = step_;
  o.joint_position_rad_or_m = joint_position();
  o.joint_velocity_rad_or_m_per_s = d_->qvel[tm_.joint.dof];
  for (const BoundHold& hold : tm_.holds) o.body_z_m.push_back(d_->qpos[hold.qpos + 2]);
  for (std::size_t i = 0; i < n_; ++i) {
    const int act = tm_.muscles[i].actuator;
    o.pressure_pa.push_back(pneumatics_.pressure_pa(static_cast<int>(i)));
    o.command_pa.push_back(pneumatics_.command_pa(static_cast<int>(i)));
    o.force_n.push_back(-pam_actuator_force(m_, d_, act));
    FreeLengthTrack track = muscle_[i].free_length;  // a look changes nothing in the trial
    o.length_m.push_back(pam_muscle_length(m_, d_, act, &track));
    o.length_est_m.push_back(readings_[i].length_est_m);
    o.velocity_est_m_s.push_back(i < out_.velocity_m_s.size() ? out_.velocity_m_s[i] : 0.0);
  }
  o.readings = readings_;
  for (const ControllerChannel& c : channels_) o.channel_names.push_back(c.prefix + c.suffix);
  o.channels = out_.channels;
  return o;
}

ControllerSetup controller_setup(const TrialModel& tm, const Scenario& sc) {
  return ControllerSetup{static_cast<int>(tm.muscles.size()), sc.control_hz, tm.pairs};
}

TrialResult run_trial(const TrialModel& model, const Scenario& scenario, std::uint64_t seed,
                      const TrialOptions& options) {
  TrialRun trial(model, scenario, seed, options);
  return trial.run();
}

// ---- SteppedTrial ----

struct SteppedTrial::State {
  Scenario scenario;
  TrialOptions options;
  std::unique_ptr<TrialRun> run;
};

SteppedTrial::SteppedTrial(const TrialModel& model, const Scenario& scenario, std::uint64_t seed)
    : model_(model), state_(std::make_unique<State>()) {
  state_->scenario = scenario;
  reset(seed);
}

SteppedTrial::~SteppedTrial() = default;

void SteppedTrial::reset(std::uint64_t seed) {
  state_->run.reset();
  // its own mjData: the caller may step, reset and destroy it from any thread
  state_->run = std::make_unique<TrialRun>(model_, state_->scenario, seed, state_->options,
                                           /*stays_on_thread=*/false);
  state_->run->begin();
}

bool SteppedTrial::step(const std::vector<double>* commands_pa) {
  TrialRun& run = *state_->run;
  if (commands_pa && commands_pa->size() != model_.muscles.size()) {
    throw InputError("step: " + std::to_string(commands_pa->size()) + " commands for " +
                     std::to_string(model_.muscles.size()) + " muscles");
  }
  run.set_external_commands(commands_pa);
  bool alive = run.step();  // the step that starts with the control tick
  run.set_external_commands(nullptr);
  while (alive && !run.control_due()) alive = run.step();
  return !done();
}

bool SteppedTrial::done() const { return state_->run->ended(); }

TrialObservation SteppedTrial::observe() const { return state_->run->observe(); }

TrialSnapshot SteppedTrial::snapshot() { return state_->run->snapshot(); }

const Scenario& SteppedTrial::scenario() const { return state_->scenario; }

double SteppedTrial::time_s() const { return state_->run->observe_time_s(); }

bool SteppedTrial::fire_event(const std::string& name) {
  for (std::size_t k = 0; k < state_->scenario.events.size(); ++k) {
    if (state_->scenario.events[k].name == name) return !done() && state_->run->fire_now(k);
  }
  throw InputError("fire_event: the scenario has no event '" + name + "'");
}

void SteppedTrial::set_controller_enabled(bool on) { state_->run->set_controller_enabled(on); }

bool SteppedTrial::controller_enabled() const { return state_->run->controller_enabled(); }

void SteppedTrial::retune_controller(const ControllerConfig& config) {
  state_->run->retune_controller(config);
}

TrialResult SteppedTrial::finish() {
  TrialResult result = state_->run->end();
  state_->run.reset();
  return result;
}

}  // namespace pamsim
