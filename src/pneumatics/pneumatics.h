// pneumatics.h: the pneumatics of all PAMs of one trial, as the co-simulation loop uses it:
// valve commands in, chamber gauge pressures out, advanced by one CVODE instance over each
// physics step. Equations: chamber_ode.h; solver: cvode_integrator.h; parameters:
// pneumatic_params.h (models/pams/pneumatics.toml).
#pragma once

#include <deque>
#include <memory>
#include <vector>

#include "pneumatics/chamber_ode.h"
#include "pam_actuator/chou_hannaford.h"
#include "pneumatics/cvode_integrator.h"
#include "pneumatics/pneumatic_params.h"
#include "pneumatics/sampled_delay_line.h"

namespace pamsim {

// Per physics step [t, t + dt] the loop calls set_kinematics() for every muscle (length and
// velocity at t; inside the step l is extrapolated linearly), then advance(t + dt). A
// controller tick calls set_command(); the command is held until changed. With the
// "regulator" valve model a command reaches the valve only after the regulator's dead time:
// advance() splits its interval at the moments delayed commands take effect. With its
// feedback "delayed" the loop's sensed pressure (the chamber's, or with sense "outlet" the
// regulator outlet's) goes through the same dead time: a sampled-data delay line
// (sampled_delay_line.h, which says why this formulation) samples it every
// [regulator] sample period and each sample acts one dead time later; advance() splits
// its interval at every sample and action too; an action steps the valve's target by what
// the sensed pressure moved in one sample, and solver.on_loop_action says whether CVODE
// restarts there ("reinit") or keeps its history ("warm", the default: a small jump).
//
// Integration strategy (measured with bench/pneumatics_bench.cc, 2 muscles, 3 Hz motion,
// a new command every 10 ms; accuracy against a rtol 1e-9 reference in pneumatics_test.cc;
// the figures below were measured with a dense linear solver; the banded one used here
// changes little for 2 muscles and takes a leg of 8 through its landing in 0.84x the time):
// - BDF with a Newton solver (banded: one block per muscle): the ISO 6358 flow function,
//   linearised near pressure equilibrium, gives time constants down to ~1 ms at 1e-8
//   m^3/(s Pa) and ~50 cm^3 (less for a larger valve or smaller chamber), i.e. the size of
//   the physics step: mildly stiff.
// - A stop time at every step end: CVODE never runs past t + dt with this step's
//   kinematics (causal; no stale-input overshoot to interpolate back from). So there is at
//   least one CVODE step per physics step (~1.1 us of CVODE overhead each, here).
// - Every physics step is a small discontinuity (ldot, hence dV/dt, is piecewise constant)
//   and every command change a large one (dp_reg/dt jumps by dp_cmd / tau_reg). With warm
//   restarts CVODE's error test rejects steps at these jumps; tight tolerances multiply the
//   steps (rtol 1e-6: ~3.5-5 steps and 5.7 us per physics step).
// - Default: rtol 1e-4, atol 1 Pa, re-initialise at command changes (solver.on_command_change
//   = "reinit"): ~1.5 steps, ~2.3 rhs evals, ~2.2 us per physics step, max pressure error
//   ~170 Pa. "warm" costs ~1.3 us (1.0 step) but reaches ~600 Pa error; rtol 1e-5 ~3.7 us
//   and ~80 Pa. The budget (1-1.5 us) is met only by "warm" at rtol 1e-4.
// - The regulator loop (BM_RegulatorLoopStep, CPU time on 2 shared cores, reinit): feedback
//   "instant" with sense "chamber" ~1.8 us; sense "outlet" ~4.2 us (a third
//   state, and the tube's laminar region is stiff); feedback "delayed" ~11.6 us and with
//   the outlet ~13.1 us with solver.on_loop_action = "reinit": every action of a 1 ms sample
//   is a jump in the valve's target, CVODE restarts there and takes ~6 steps per physics
//   step (with commands every 10 ms and "warm" everywhere: ~8 smaller ones).
//   On the drop trial, where commands change at 100 Hz and the loop acts every 1 ms,
//   solver.on_loop_action = "warm" takes 1.0 step and 1.1 rhs evaluations per physics step
//   against 2.0 and 10.5 with "reinit" (chamber within 0.42 against 0.31 kPa of a rtol 1e-9
//   reference; regulator_loop_test.cc).
class PneumaticSystem {
 public:
  // One CVODE instance for all muscles. braid[i] gives muscle i's chamber volume law.
  // initial_gauge_pa[i] in [0, supply] is muscle i's chamber (and regulator) pressure and
  // its initial command. Throws InputError for invalid params, sizes or pressures, and
  // IntegrationError if SUNDIALS cannot be set up.
  PneumaticSystem(const PneumaticParams& params, ValveModel model, std::vector<BraidGeometry> braid,
                  std::vector<double> initial_gauge_pa, double t0_s = 0.0);
  ~PneumaticSystem();
  PneumaticSystem(const PneumaticSystem&) = delete;
  PneumaticSystem& operator=(const PneumaticSystem&) = delete;

  int muscle_count() const;
  // gauge [Pa], clamped to the valve's command range [command_min, command_max] (within
  // [0, supply]); held until changed (a control tick; a discontinuity). Throws
  // std::out_of_range for a bad muscle index, std::invalid_argument for a non-finite value.
  void set_command(int muscle, double p_cmd_gauge_pa);
  // a physical muscle's chamber volume law (PneumaticOde::set_plant_volume); before the
  // first advance(). Throws std::out_of_range for a bad muscle index.
  void set_plant_volume(int muscle, const AvbdlParams& plant);
  // braided length [m] in (0, fibre length) and its rate [m/s] at the start of each physics
  // step (time_s()). Throws std::out_of_range / std::invalid_argument.
  void set_kinematics(int muscle, double length_m, double velocity_m_s);
  // integrate from time_s() to t_end_s >= time_s(); throws IntegrationError, and
  // std::logic_error if a muscle's kinematics were never set
  void advance(double t_end_s);
  double time_s() const;
  double pressure_pa(int muscle) const;            // chamber gauge pressure at time_s()
  double regulator_pressure_pa(int muscle) const;  // gauge; the chamber model's source
                                                   // (first_order, regulator: the command
                                                   // as issued, before any dead time)
  double command_pa(int muscle) const;             // gauge, after clamping
  // gauge; the regulator's outlet port (sense = "outlet"), else the chamber's pressure
  double outlet_pressure_pa(int muscle) const;

  // solver statistics for the benchmark note (cumulative)
  long steps() const;
  long rhs_evals() const;
  long reinits() const { return reinits_; }

 private:
  void check_muscle(int muscle) const;
  std::vector<double> current_state() const;
  void integrate_to(double t_s);  // restarting first if a command changed
  void apply_command(int muscle, double p_cmd_abs_pa);
  // the next delayed command, loop sample or loop action (+inf if none)
  double next_event_s() const;
  // applies the delayed commands due by t_s, then takes the loop's samples and its
  // actions due by then
  void handle_events_due(double t_s);

  // a command on its way to the valve (the regulator's dead time)
  struct DelayedCommand {
    double t_s;
    int muscle;
    double p_cmd_abs_pa;
  };
  std::deque<DelayedCommand> delayed_;
  double dead_time_s_ = 0.0;
  // the loop's sensed pressures on their way (feedback = "delayed"); empty otherwise
  std::unique_ptr<SampledDelayLine> feedback_;

  PneumaticParams params_;
  std::unique_ptr<PneumaticOde> ode_;
  std::unique_ptr<CvodeIntegrator> integrator_;  // refers to *ode_: declared after it
  std::vector<double> command_gauge_pa_;
  std::vector<bool> kinematics_set_;
  bool reinit_pending_ = false;
  long reinits_ = 0;
};

}  // namespace pamsim
