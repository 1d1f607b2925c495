// pneumatics.cc: PneumaticSystem, the valve + chamber pneumatics of one trial (see header).
#include "pneumatics/pneumatics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "base/input_error.h"

namespace pamsim {

PneumaticSystem::PneumaticSystem(const PneumaticParams& params, ValveModel model,
                                 std::vector<BraidGeometry> braid,
                                 std::vector<double> initial_gauge_pa, double t0_s)
    : params_(params) {
  // validate sizes and initial pressures
  if (initial_gauge_pa.size() != braid.size()) {
    throw InputError("pneumatic system: " + std::to_string(braid.size()) + " muscles but " +
                     std::to_string(initial_gauge_pa.size()) + " initial pressures");
  }
  for (std::size_t i = 0; i < initial_gauge_pa.size(); ++i) {
    const double p = initial_gauge_pa[i];
    if (!(p >= 0.0 && p <= params_.supply_gauge_pa)) {
      throw InputError("pneumatic system: muscle " + std::to_string(i) +
                       ": initial pressure must be in [0, " +
                       std::to_string(params_.supply_gauge_pa) + "] Pa, got " + std::to_string(p));
    }
  }
  ode_ = std::make_unique<PneumaticOde>(params_, model, std::move(braid));

  // commands start at the initial pressures: the system starts in equilibrium
  const int n = ode_->muscle_count();
  command_gauge_pa_.assign(n, 0.0);
  kinematics_set_.assign(n, false);
  for (int i = 0; i < n; ++i) {
    command_gauge_pa_[i] = initial_gauge_pa[i];
    ode_->set_command_abs(i, initial_gauge_pa[i] + params_.atmospheric_pa);
    set_command(i, initial_gauge_pa[i]);  // clamps into the command range
  }
  reinit_pending_ = false;
  // from here on commands reach the valve after the regulator's dead time
  dead_time_s_ = model == ValveModel::kRegulator ? params_.regulator_dead_time_s : 0.0;

  std::vector<double> y0(ode_->size());
  std::vector<double> sensed(n);
  for (int i = 0; i < n; ++i) {
    const double p_abs = initial_gauge_pa[i] + params_.atmospheric_pa;
    y0[ode_->chamber_index(i)] = p_abs;
    if (ode_->regulator_index(i) >= 0) y0[ode_->regulator_index(i)] = p_abs;
    if (ode_->valve_opening_index(i) >= 0) y0[ode_->valve_opening_index(i)] = 0.0;  // at rest
    if (ode_->outlet_index(i) >= 0) y0[ode_->outlet_index(i)] = p_abs;
    sensed[i] = p_abs;
    ode_->set_sensed_abs(i, p_abs);
  }
  // the loop's delay line starts at rest: its first sample is the initial pressure
  if (model == ValveModel::kRegulator &&
      params_.regulator_feedback == RegulatorFeedback::kDelayed) {
    feedback_ = std::make_unique<SampledDelayLine>(t0_s, params_.regulator_sample_period_s,
                                                   dead_time_s_, std::move(sensed));
  }
  CvodeOptions options;
  options.method = params_.solver.method;
  options.relative_tolerance = params_.solver.relative_tolerance;
  options.absolute_tolerance = params_.solver.absolute_tolerance_pa;
  integrator_ = std::make_unique<CvodeIntegrator>(*ode_, options, t0_s, y0);
}

PneumaticSystem::~PneumaticSystem() = default;

int PneumaticSystem::muscle_count() const { return ode_->muscle_count(); }

void PneumaticSystem::check_muscle(int muscle) const {
  if (muscle < 0 || muscle >= muscle_count()) {
    throw std::out_of_range("pneumatic system: muscle index " + std::to_string(muscle) +
                            " out of range [0, " + std::to_string(muscle_count()) + ")");
  }
}

void PneumaticSystem::set_command(int muscle, double p_cmd_gauge_pa) {
  check_muscle(muscle);
  if (!std::isfinite(p_cmd_gauge_pa)) {
    throw std::invalid_argument("pneumatic system: muscle " + std::to_string(muscle) +
                                ": non-finite valve command");
  }
  // the regulator accepts only its command range
  const double p =
      std::clamp(p_cmd_gauge_pa, params_.command_min_gauge_pa, params_.command_max_gauge_pa);
  if (p == command_gauge_pa_[muscle]) return;
  command_gauge_pa_[muscle] = p;
  if (dead_time_s_ > 0.0) {
    delayed_.push_back({integrator_->time() + dead_time_s_, muscle, p + params_.atmospheric_pa});
    return;
  }
  apply_command(muscle, p + params_.atmospheric_pa);
}

void PneumaticSystem::apply_command(int muscle, double p_cmd_abs_pa) {
  ode_->set_command_abs(muscle, p_cmd_abs_pa);
  if (params_.solver.on_command_change == CommandChangePolicy::kReinit) reinit_pending_ = true;
}

void PneumaticSystem::set_plant_volume(int muscle, const AvbdlParams& plant) {
  check_muscle(muscle);
  ode_->set_plant_volume(muscle, plant);
}

void PneumaticSystem::set_kinematics(int muscle, double length_m, double velocity_m_s) {
  check_muscle(muscle);
  if (!std::isfinite(length_m) || !std::isfinite(velocity_m_s)) {
    throw std::invalid_argument("pneumatic system: muscle " + std::to_string(muscle) +
                                ": non-finite length or velocity");
  }
  // the Chou-Hannaford volume is positive only for 0 < l < b
  const double b = ode_->braid(muscle).fibre_length_m;
  if (!(length_m > 0.0 && length_m < b)) {
    throw std::invalid_argument("pneumatic system: muscle " + std::to_string(muscle) +
                                ": length must be in (0, " + std::to_string(b) + ") m, got " +
                                std::to_string(length_m));
  }
  ode_->set_kinematics(muscle, integrator_->time(), length_m, velocity_m_s);
  kinematics_set_[muscle] = true;
}

std::vector<double> PneumaticSystem::current_state() const {
  const double* y = integrator_->state();
  return std::vector<double>(y, y + integrator_->size());
}

void PneumaticSystem::advance(double t_end_s) {
  for (int i = 0; i < muscle_count(); ++i) {
    if (!kinematics_set_[i]) {
      throw std::logic_error("pneumatic system: muscle " + std::to_string(i) +
                             ": set_kinematics() was never called");
    }
  }
  // delayed commands and the loop's samples and actions inside the interval split it
  // there; those due at its end apply from the next one
  constexpr double kSameTimeS = 1e-12;
  for (double t = next_event_s(); t < t_end_s - kSameTimeS; t = next_event_s()) {
    if (t > time_s() + kSameTimeS) integrate_to(t);
    handle_events_due(t + kSameTimeS);
  }
  integrate_to(t_end_s);
  handle_events_due(t_end_s + kSameTimeS);
}

double PneumaticSystem::next_event_s() const {
  double t = delayed_.empty() ? std::numeric_limits<double>::infinity() : delayed_.front().t_s;
  if (feedback_) t = std::min(t, feedback_->next_event_s());
  return t;
}

void PneumaticSystem::handle_events_due(double t_s) {
  while (!delayed_.empty() && delayed_.front().t_s <= t_s) {
    apply_command(delayed_.front().muscle, delayed_.front().p_cmd_abs_pa);
    delayed_.pop_front();
  }
  if (!feedback_) return;
  // the loop samples what it senses now; a sample whose dead time is over acts
  while (feedback_->next_sample_s() <= t_s) {
    std::vector<double> sample(muscle_count());
    for (int i = 0; i < muscle_count(); ++i) {
      sample[i] = integrator_->state()[ode_->sensed_index(i)];
    }
    feedback_->take_sample(std::move(sample));
  }
  while (feedback_->next_action_s() <= t_s) {
    if (!feedback_->act()) continue;
    for (int i = 0; i < muscle_count(); ++i) ode_->set_sensed_abs(i, feedback_->held()[i]);
    if (params_.solver.on_loop_action == CommandChangePolicy::kReinit) reinit_pending_ = true;
  }
}

void PneumaticSystem::integrate_to(double t_s) {
  // optional restart at a command change (solver.on_command_change = "reinit")
  if (reinit_pending_) {
    integrator_->reset(integrator_->time(), current_state());
    reinit_pending_ = false;
    ++reinits_;
  }
  integrator_->advance_to(t_s);
}

double PneumaticSystem::time_s() const { return integrator_->time(); }

double PneumaticSystem::pressure_pa(int muscle) const {
  check_muscle(muscle);
  return integrator_->state()[ode_->chamber_index(muscle)] - params_.atmospheric_pa;
}

double PneumaticSystem::regulator_pressure_pa(int muscle) const {
  check_muscle(muscle);
  const int k = ode_->regulator_index(muscle);
  if (k < 0) return command_gauge_pa_[muscle];
  return integrator_->state()[k] - params_.atmospheric_pa;
}

double PneumaticSystem::outlet_pressure_pa(int muscle) const {
  check_muscle(muscle);
  return integrator_->state()[ode_->sensed_index(muscle)] - params_.atmospheric_pa;
}

double PneumaticSystem::command_pa(int muscle) const {
  check_muscle(muscle);
  return command_gauge_pa_[muscle];
}

long PneumaticSystem::steps() const { return integrator_->steps(); }
long PneumaticSystem::rhs_evals() const { return integrator_->rhs_evals(); }

}  // namespace pamsim
