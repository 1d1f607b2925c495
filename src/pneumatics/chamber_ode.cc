// chamber_ode.cc: valve + chamber right-hand side (see chamber_ode.h for the equations).
#include "pneumatics/chamber_ode.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <string>
#include <utility>

#include "base/enum_names.h"
#include "base/input_error.h"

namespace pamsim {

namespace {
constexpr EnumName<ValveModel> kValveNames[] = {{ValveModel::kIso6358, "iso6358"},
                                                {ValveModel::kFirstOrder, "first_order"},
                                                {ValveModel::kRegulator, "regulator"}};
}  // namespace

const char* valve_model_name(ValveModel model) { return name_of(kValveNames, model); }

ChoiceRow valve_model_row(std::string name, ValveModel* model) {
  return enum_choice_row(std::move(name), kValveNames,
                         "the valve and chamber model: ISO 6358 orifices, a first-order lag, "
                         "or the proportional pressure regulator's loop",
                         model);
}

double iso6358_flow_function(double r, double b, double r_lam) {
  // choked (sonic) flow
  if (r <= b) return 1.0;
  // subsonic ellipse of ISO 6358-1
  auto ellipse = [b](double x) {
    const double s = (x - b) / (1.0 - b);
    return std::sqrt(std::max(0.0, 1.0 - s * s));
  };
  if (r <= r_lam) return ellipse(r);
  // laminar linearisation to zero flow at r = 1 (finite slope at equilibrium)
  return ellipse(r_lam) * (1.0 - std::min(r, 1.0)) / (1.0 - r_lam);
}

double iso6358_mass_flow(const PneumaticParams& p, double p_up_pa, double p_down_pa) {
  assert(p_up_pa > 0.0 && p_down_pa <= p_up_pa);
  const double psi =
      iso6358_flow_function(p_down_pa / p_up_pa, p.critical_pressure_ratio, p.laminar_ratio);
  return p.sonic_conductance_m3_per_s_pa * kIso6358ReferenceDensityKgM3 * p_up_pa *
         std::sqrt(kIso6358ReferenceTemperatureK / p.temperature_k) * psi;
}

PneumaticOde::PneumaticOde(const PneumaticParams& params, ValveModel model,
                           std::vector<BraidGeometry> braid)
    : params_(params), model_(model), braid_(std::move(braid)) {
  validate_pneumatic_params(params_, "pneumatic parameters");
  if (braid_.empty()) throw InputError("pneumatic ODE: at least one muscle is required");
  for (std::size_t i = 0; i < braid_.size(); ++i) {
    if (!(braid_[i].fibre_length_m > 0.0) || !(braid_[i].turns > 0.0)) {
      throw InputError("pneumatic ODE: muscle " + std::to_string(i) +
                       ": braid fibre length and turns must be > 0");
    }
  }
  input_.resize(braid_.size());
  plant_.resize(braid_.size());
  shape_.resize(braid_.size());
  for (Input& in : input_) in.p_cmd_abs = in.p_sensed_abs = params_.atmospheric_pa;
  // ISO 6358-1: qm = C rho0 p_up sqrt(T0/T) psi(r); each restriction's C rho0 sqrt(T0/T)
  const auto coefficient = [this](double c) {
    return c * kIso6358ReferenceDensityKgM3 *
           std::sqrt(kIso6358ReferenceTemperatureK / params_.temperature_k);
  };
  path_ = {coefficient(params_.sonic_conductance_m3_per_s_pa), params_.critical_pressure_ratio};
  supply_ = {coefficient(regulator_supply_conductance(params_)),
             regulator_supply_critical_ratio(params_)};
  exhaust_ = {coefficient(regulator_exhaust_conductance(params_)),
              regulator_exhaust_critical_ratio(params_)};
  tube_ = {coefficient(params_.tube_conductance_m3_per_s_pa), params_.tube_critical_ratio};
  n_r_t_ = params_.polytropic_index * params_.gas_constant_j_per_kg_k * params_.temperature_k;
}

int PneumaticOde::states_per_muscle() const {
  if (model_ == ValveModel::kFirstOrder) return 1;
  const bool outlet =
      model_ == ValveModel::kRegulator && params_.regulator_sense == RegulatorSense::kOutlet;
  return outlet ? 3 : 2;
}

int PneumaticOde::chamber_index(int muscle) const {
  return model_ == ValveModel::kFirstOrder ? muscle : states_per_muscle() * muscle + 1;
}

int PneumaticOde::regulator_index(int muscle) const {
  return model_ == ValveModel::kIso6358 ? 2 * muscle : -1;
}

int PneumaticOde::valve_opening_index(int muscle) const {
  return model_ == ValveModel::kRegulator ? states_per_muscle() * muscle : -1;
}

int PneumaticOde::outlet_index(int muscle) const {
  return states_per_muscle() == 3 ? 3 * muscle + 2 : -1;
}

int PneumaticOde::sensed_index(int muscle) const {
  const int k = outlet_index(muscle);
  return k >= 0 ? k : chamber_index(muscle);
}

double PneumaticOde::restriction_flow(const Restriction& r, double opening, double p_a,
                                      double p_b) const {
  const double r_lam = params_.laminar_ratio;
  if (p_a >= p_b) {
    return opening * r.coefficient * p_a * iso6358_flow_function(p_b / p_a, r.b, r_lam);
  }
  return -opening * r.coefficient * p_b * iso6358_flow_function(p_a / p_b, r.b, r_lam);
}

void PneumaticOde::regulator_rhs(double t, const double* y, double* ydot) {
  const double inv_tau_v = 1.0 / params_.regulator_valve_time_constant_s;
  const double band = params_.regulator_proportional_band_pa;
  const double p_supply = params_.supply_gauge_pa + params_.atmospheric_pa;
  const double p_atm = params_.atmospheric_pa;
  const bool outlet = params_.regulator_sense == RegulatorSense::kOutlet;
  const bool delayed = params_.regulator_feedback == RegulatorFeedback::kDelayed;
  for (int i = 0; i < muscle_count(); ++i) {
    const int k = valve_opening_index(i);
    const double u = y[k];
    const double p = y[k + 1];
    // the valve feeds the regulator's outlet volume (sense = "outlet") or the chamber
    const double p_node = outlet ? y[k + 2] : p;
    if (!(p > 0.0) || !(p_node > 0.0)) {
      throw RecoverableRhsError("non-positive absolute pressure");
    }

    // the main valve opens toward the error of the sensed pressure (as it is now, or the
    // sample the loop took one dead time ago), with its own lag
    const double p_sensed = delayed ? input_[i].p_sensed_abs : p_node;
    const double target = std::clamp((input_[i].p_cmd_abs - p_sensed) / band, -1.0, 1.0);
    ydot[k] = (target - u) * inv_tau_v;

    // filling from the supply, or venting to the atmosphere
    const double qm_valve = u >= 0.0 ? restriction_flow(supply_, u, p_supply, p_node)
                                     : -restriction_flow(exhaust_, -u, p_node, p_atm);

    // outlet volume (rigid, polytropic) -> tube and fittings -> chamber
    double qm_in = qm_valve;
    if (outlet) {
      qm_in = restriction_flow(tube_, 1.0, p_node, p);
      ydot[k + 2] = n_r_t_ * (qm_valve - qm_in) / params_.regulator_outlet_volume_m3;
    }

    // polytropic chamber with moving wall
    const double volume = volume_m3(i, t);
    if (!(volume > 0.0)) throw RecoverableRhsError("non-positive chamber volume");
    ydot[k + 1] = (n_r_t_ * qm_in - params_.polytropic_index * p * volume_rate_m3_s(i, t)) / volume;
  }
}

void PneumaticOde::set_kinematics(int muscle, double t0_s, double length_m, double velocity_m_s) {
  Input& in = input_[muscle];
  in.t0 = t0_s;
  in.l0 = length_m;
  in.ldot = velocity_m_s;
}

void PneumaticOde::set_plant_volume(int muscle, const AvbdlParams& plant) {
  validate_avbdl_params(plant, "plant.");
  plant_.at(static_cast<std::size_t>(muscle)) = plant;
  shape_[static_cast<std::size_t>(muscle)] = avbdl_shape(plant);
  braid_[static_cast<std::size_t>(muscle)] = avbdl_braid(plant);  // its length limits
}

double PneumaticOde::volume_m3(int muscle, double t) const {
  const Input& in = input_[muscle];
  const double l = in.l0 + in.ldot * (t - in.t0);
  if (plant_[muscle]) {
    return avbdl_volume(*plant_[muscle], shape_[muscle], l) + params_.tube_dead_volume_m3;
  }
  return chou_hannaford_volume(braid_[muscle], l) + params_.tube_dead_volume_m3;
}

double PneumaticOde::volume_rate_m3_s(int muscle, double t) const {
  const Input& in = input_[muscle];
  const double l = in.l0 + in.ldot * (t - in.t0);
  if (plant_[muscle]) return avbdl_dvolume_dlength(*plant_[muscle], shape_[muscle], l) * in.ldot;
  return chou_hannaford_dvolume_dlength(braid_[muscle], l) * in.ldot;
}

void PneumaticOde::rhs(double t, const double* y, double* ydot) {
  const int n_muscles = muscle_count();
  if (model_ == ValveModel::kFirstOrder) {
    // first-order lag toward the held command
    const double inv_tau = 1.0 / params_.first_order_time_constant_s;
    for (int i = 0; i < n_muscles; ++i) ydot[i] = (input_[i].p_cmd_abs - y[i]) * inv_tau;
    return;
  }
  if (model_ == ValveModel::kRegulator) {
    regulator_rhs(t, y, ydot);
    return;
  }

  const double inv_tau_reg = 1.0 / params_.regulator_time_constant_s;
  const double n = params_.polytropic_index;
  for (int i = 0; i < n_muscles; ++i) {
    const double p_reg = y[2 * i];
    const double p = y[2 * i + 1];
    // the Newton iteration may probe states outside the gas model's domain: retry smaller
    if (!(p > 0.0) || !(p_reg > 0.0)) {
      throw RecoverableRhsError("non-positive absolute pressure");
    }

    // regulator output follows the command
    ydot[2 * i] = (input_[i].p_cmd_abs - p_reg) * inv_tau_reg;

    // ISO 6358 flow: in from the regulator, or out through its relief port
    const double qm_in = restriction_flow(path_, 1.0, p_reg, p);

    // polytropic chamber with moving wall
    const double volume = volume_m3(i, t);
    if (!(volume > 0.0)) throw RecoverableRhsError("non-positive chamber volume");
    const double volume_rate = volume_rate_m3_s(i, t);
    ydot[2 * i + 1] = (n_r_t_ * qm_in - n * p * volume_rate) / volume;
  }
}

}  // namespace pamsim
