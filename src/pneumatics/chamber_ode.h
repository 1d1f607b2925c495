// chamber_ode.h: the right-hand side of the valve + muscle-chamber ODE, without any solver.
// PneumaticOde implements the small f(t, y) -> ydot interface that CvodeIntegrator
// integrates (ode_system.h: Cantera's split between a reactor's equations and the
// integrator) for N muscles with one of three valve models (ValveModel). Inputs per muscle,
// held over a step: command (absolute Pa inside this class), length l0 [m] and velocity
// ldot [m/s] at time t0 [s]; inside the step l(t) = l0 + ldot (t - t0), so V(t) and dV/dt
// are consistent.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "pam_actuator/avbdl.h"
#include "pam_actuator/chou_hannaford.h"
#include "pneumatics/ode_system.h"
#include "pneumatics/pneumatic_params.h"

namespace pamsim {

// kIso6358 (two states per muscle, absolute pressures [Pa]):
//   regulator  dp_reg/dt = (p_cmd - p_reg) / tau_reg                (first-order regulator)
//   restriction (ISO 6358-1) qm = C rho0 p_up sqrt(T0/T) psi(r),  r = p_down / p_up,
//     psi(r) = 1 for r <= b,  sqrt(1 - ((r-b)/(1-b))^2) for b < r <= r_lam,
//     psi(r) = psi(r_lam) (1 - r) / (1 - r_lam) for r > r_lam  (laminar linearisation),
//     filling (p_reg > p): p_up = p_reg, p_down = p, air flows in;
//     venting (p > p_reg): p_up = p, p_down = p_reg, air leaves through the relief port;
//   chamber    dp/dt = n R T / V qm_in - n p / V dV/dt,  V = V_CH(l) + V_dead,
//              dV/dt = dV_CH/dl * ldot   (Chou-Hannaford volume, chou_hannaford.h; a
//              muscle with a physical plant uses its AVBDL volume instead).
// kFirstOrder (one state per muscle): dp/dt = (p_cmd - p) / tau; the analytic step
//   response is p(t) = p_cmd + (p0 - p_cmd) exp(-t / tau).
// kRegulator (two states per muscle: the main valve's opening u in [-1, 1], and p): a
//   proportional pressure regulator as a closed loop around the chamber it feeds, so that
//   the chamber is not an ideal pressure source: the command arrives after a dead time
//   (PneumaticSystem delays it); the valve opens toward the pressure error,
//     du/dt = (clamp((p_cmd - p_s) / p_band, -1, 1) - u) / tau_v,
//   filling from the supply (u > 0) through the supply restriction (C_s, b_s) or venting to
//   the atmosphere (u < 0) through the exhaust restriction (C_e, b_e), each ISO 6358 flow
//   scaled by |u| (C_s = C_e = the [valve] C unless [regulator] gives them); the chamber
//   equation as above. A stretch compresses the chamber faster than the valve can vent, so
//   its pressure rises toward the closed chamber's p V^n = const until the loop catches up.
//   The sensed pressure p_s ([regulator] sense, feedback):
//   - sense "chamber" (default): the valve feeds the chamber and senses it, p_s = p;
//   - sense "outlet" (a third state p_o): the valve feeds the regulator's own outlet volume
//     V_o and senses there, as an SMC ITV's pressure sensor does; the tube and fittings are
//     a restriction (C_t, b_t) from the outlet to the chamber (the tube's volume stays with
//     the chamber), p_s = p_o and
//       dp_o/dt = n R T / V_o (qm_valve - qm_tube),  the chamber fed by qm_tube;
//   - feedback "instant" (default): p_s as it is now; "delayed": p_s is the sample the
//     regulator took one dead time ago (set_sensed_abs(), held between samples;
//     PneumaticSystem keeps the delay line), so a disturbance, like a command, is answered
//     only after the dead time.
enum class ValveModel { kIso6358, kFirstOrder, kRegulator };

// The name a file gives `model`: "iso6358", "first_order" or "regulator".
const char* valve_model_name(ValveModel model);
// A scenario's valve.model (the key `name` of its table), bound to `model`: its names are
// valve_model_name's, read back to the model they name.
ChoiceRow valve_model_row(std::string name, ValveModel* model);

// ISO 6358 flow function psi(r) with the laminar linearisation above r_lam (see above);
// r = p_down / p_up in [0, 1]. b in [0, 1), r_lam in (b, 1).
double iso6358_flow_function(double r, double b, double r_lam);

// ISO 6358 mass flow [kg/s] from p_up to p_down (absolute Pa, p_up >= p_down > 0) through
// sonic conductance C [m^3/(s Pa)] with gas at temperature T [K].
double iso6358_mass_flow(const PneumaticParams& params, double p_up_pa, double p_down_pa);

class PneumaticOde : public OdeSystem {
 public:
  // One muscle per braid entry. Throws InputError if params fail validation or braid is
  // empty / has non-positive fibre length or turns.
  PneumaticOde(const PneumaticParams& params, ValveModel model, std::vector<BraidGeometry> braid);

  int size() const override { return states_per_muscle() * muscle_count(); }
  void rhs(double t, const double* y, double* ydot) override;
  // each muscle's states depend on its own alone (a block of states_per_muscle())
  int half_bandwidth() const override { return states_per_muscle() - 1; }

  int muscle_count() const { return static_cast<int>(braid_.size()); }
  // 1 (first_order), 2 (iso6358; regulator sensing the chamber), 3 (regulator sensing
  // its outlet)
  int states_per_muscle() const;
  // index in y of muscle i's chamber pressure, of its regulator pressure, of its valve
  // opening and of its regulator outlet pressure (-1 when the model has none)
  int chamber_index(int muscle) const;
  int regulator_index(int muscle) const;
  int valve_opening_index(int muscle) const;
  int outlet_index(int muscle) const;
  // the pressure the regulator's loop senses: its outlet's, else the chamber's
  int sensed_index(int muscle) const;
  ValveModel model() const { return model_; }
  const BraidGeometry& braid(int muscle) const { return braid_[muscle]; }
  const PneumaticParams& params() const { return params_; }

  // held inputs: command as absolute pressure [Pa]; kinematics at time t0_s
  void set_command_abs(int muscle, double p_cmd_abs_pa) { input_[muscle].p_cmd_abs = p_cmd_abs_pa; }
  // regulator feedback "delayed": the sensed pressure [Pa, absolute] its loop acts on now
  // (a sample taken one dead time ago; PneumaticSystem holds the delay line)
  void set_sensed_abs(int muscle, double p_sensed_abs_pa) {
    input_[muscle].p_sensed_abs = p_sensed_abs_pa;
  }
  void set_kinematics(int muscle, double t0_s, double length_m, double velocity_m_s);
  // a physical muscle's chamber: V(l) from the AVBDL shape (avbdl.h, Pipan et al.,
  // Eq. (9)-(17)) in place of Chou-Hannaford's cylinder; the plant (validated, InputError)
  // also gives the muscle's braid. Throws std::out_of_range for a bad muscle index.
  void set_plant_volume(int muscle, const AvbdlParams& plant);
  // total gas volume V = V(l(t)) + V_dead [m^3] and its rate [m^3/s] at time t
  double volume_m3(int muscle, double t) const;
  double volume_rate_m3_s(int muscle, double t) const;

 private:
  struct Input {
    double p_cmd_abs = 0.0;
    double p_sensed_abs = 0.0;
    double t0 = 0.0;
    double l0 = 0.0;
    double ldot = 0.0;
  };
  PneumaticParams params_;
  ValveModel model_;
  std::vector<BraidGeometry> braid_;
  std::vector<std::optional<AvbdlParams>> plant_;  // per muscle, when set_plant_volume
  std::vector<AvbdlShape> shape_;                  // the plant's shape, derived once
  std::vector<Input> input_;
  // an ISO 6358 restriction: C rho0 sqrt(T0/T) [kg/(s Pa)] and b
  struct Restriction {
    double coefficient = 0.0;
    double b = 0.0;
  };
  void regulator_rhs(double t, const double* y, double* ydot);
  // signed mass flow [kg/s] from a gas at p_a to one at p_b (absolute Pa) through the
  // restriction r opened to `opening` in [0, 1]
  double restriction_flow(const Restriction& r, double opening, double p_a, double p_b) const;

  Restriction path_;     // iso6358: regulator -> tube -> chamber ([valve])
  Restriction supply_;   // regulator: supply -> outlet (or chamber)
  Restriction exhaust_;  // regulator: outlet (or chamber) -> atmosphere
  Restriction tube_;     // regulator sensing its outlet: outlet -> chamber
  double n_r_t_ = 0.0;   // n R T
};

}  // namespace pamsim
