// regulator_loop_test.cc: the "regulator" valve model's loop (chamber_ode.h, pneumatics.h,
// sampled_delay_line.h): with feedback "delayed" a stretch is answered only
// after the dead time (until then the chamber is the closed chamber of p V^n = const); the
// delayed loop without dead time tends to the instant loop as its sample period shrinks;
// sensing at the outlet tends to sensing in the chamber as the tube stiffens; every
// combination settles on the command with outlet and chamber equal; separate supply and
// exhaust capacities give fill and vent times in the ISO 6358 choked-flow ratio; the tube
// conserves mass; and the delay line itself samples and acts on time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/units.h"
#include "pneumatics/pneumatics.h"
#include "pneumatics/sampled_delay_line.h"
#include "pneumatics/pneumatics_test_util.h"

namespace pamsim {
namespace {

using pamsim_test::kDt;
using pamsim_test::kLength;
using pamsim_test::table_one_braid;

constexpr double kBarToPa = 1e5;  // dm^3/(s bar) -> m^3/(s Pa): 1e-3 / kBarToPa

// a loop that is stable with its feedback delayed: a band wide enough for the dead time
PneumaticParams loop_params(RegulatorFeedback feedback, RegulatorSense sense) {
  PneumaticParams p;
  p.regulator_feedback = feedback;
  p.regulator_sense = sense;
  p.regulator_proportional_band_pa = 300e3;
  p.solver.relative_tolerance = 1e-8;
  p.solver.absolute_tolerance_pa = 1e-4;
  // the model's own answers: CVODE restarts at every jump of the loop (a stiff 20 kPa loop
  // sampled at 0.05 ms jumps by more than this tolerance allows a warm step to absorb)
  p.solver.on_loop_action = CommandChangePolicy::kReinit;
  return p;
}

// chamber pressures [Pa gauge] after each physics step: at rest for `rest` steps, then a
// command step to p_cmd, or a stretch at `velocity` for `moving` steps, then held
struct Trace {
  std::vector<double> chamber, outlet;
  double length_end = kLength;
};
Trace run(const PneumaticParams& params, double p_cmd, double velocity, int rest, int moving,
          int total, double dt = kDt) {
  PneumaticSystem sys(params, ValveModel::kRegulator, {table_one_braid()}, {0.4e6});
  Trace r;
  double l = kLength;
  for (int k = 0; k < total; ++k) {
    if (k == rest) sys.set_command(0, p_cmd);
    const double v = (k >= rest && k < rest + moving) ? velocity : 0.0;
    sys.set_kinematics(0, l, v);
    sys.advance((k + 1) * dt);
    l += v * dt;
    r.chamber.push_back(sys.pressure_pa(0));
    r.outlet.push_back(sys.outlet_pressure_pa(0));
  }
  r.length_end = l;
  return r;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, std::fabs(a[k] - b[k]));
  return worst;
}

// closed chamber under the stretch from kLength at `velocity` starting at step `rest`:
// p V^n = const (the valve shut, chamber_ode.h)
double closed_chamber_pa(const PneumaticParams& params, double velocity, int rest, int k) {
  const BraidGeometry g = table_one_braid();
  const double l = kLength + velocity * kDt * std::max(0, k + 1 - rest);
  const double v0 = chou_hannaford_volume(g, kLength) + params.tube_dead_volume_m3;
  const double v = chou_hannaford_volume(g, l) + params.tube_dead_volume_m3;
  const double p0 = 0.4e6 + params.atmospheric_pa;
  return p0 * std::pow(v0 / v, params.polytropic_index) - params.atmospheric_pa;
}

// A stretch from t = 50 ms: the sample at 50 ms still reads the rest pressure, the one at
// 51 ms the first rise, which acts at 51 ms + D: the latency is the dead time plus at most
// one sample period. Until then the valve stays shut and the chamber is closed,
// p V^n = const to the solver's tolerance; right after, the loop vents.
TEST(RegulatorLoopTest, DelayedFeedbackAnswersAStretchOnlyAfterTheDeadTime) {
  constexpr int kRest = 50;
  constexpr double kVelocity = 0.1;  // the impact's 100 mm/s
  for (double dead_ms : {5.0, 10.0, 20.0}) {
    SCOPED_TRACE(dead_ms);
    PneumaticParams params = loop_params(RegulatorFeedback::kDelayed, RegulatorSense::kChamber);
    params.regulator_dead_time_s = dead_ms * 1e-3;
    params.regulator_valve_time_constant_s = 2e-3;
    const Trace r = run(params, 0.4e6, kVelocity, kRest, 40, 90);
    const int answered = kRest + 1 + static_cast<int>(dead_ms);  // step ending at 51 ms + D
    for (int k = kRest; k < answered; ++k) {
      const double closed = closed_chamber_pa(params, kVelocity, kRest, k);
      EXPECT_NEAR(r.chamber[k], closed, 0.05) << "t = " << k + 1 << " ms: passive";
    }
    EXPECT_GT(r.chamber[answered - 1] - 0.4e6, 1e3) << "the stretch has raised it";
    // the first millisecond of venting already shows (~3 Pa, against ~1e-3 Pa of solver
    // error), and it grows
    const auto vented = [&](int k) {
      return closed_chamber_pa(params, kVelocity, kRest, k) - r.chamber[k];
    };
    EXPECT_GT(vented(answered), 1.0) << "answered 1 ms after the action";
    EXPECT_GT(vented(answered + 5), 100.0);
  }
  // the instant loop answers at once
  PneumaticParams instant = loop_params(RegulatorFeedback::kInstant, RegulatorSense::kChamber);
  instant.regulator_valve_time_constant_s = 2e-3;
  const Trace r = run(instant, 0.4e6, kVelocity, kRest, 40, 60);
  EXPECT_LT(r.chamber[kRest + 2], closed_chamber_pa(instant, kVelocity, kRest, kRest + 2) - 20.0);
}

// Without dead time the delayed loop is the instant one through a zero-order hold of
// period T: the difference shrinks with T (about in proportion).
TEST(RegulatorLoopTest, DelayedFeedbackWithoutDeadTimeTendsToTheInstantLoop) {
  PneumaticParams instant = loop_params(RegulatorFeedback::kInstant, RegulatorSense::kChamber);
  instant.regulator_dead_time_s = 0.0;
  instant.regulator_proportional_band_pa = 20e3;  // the shipped band: stiff loop
  const Trace ref = run(instant, 0.5e6, 0.1, 20, 20, 150);
  double previous = INFINITY;
  for (double period_ms : {0.2, 0.1, 0.05}) {
    SCOPED_TRACE(period_ms);
    PneumaticParams delayed = instant;
    delayed.regulator_feedback = RegulatorFeedback::kDelayed;
    delayed.regulator_sample_period_s = period_ms * 1e-3;
    const double d = max_difference(run(delayed, 0.5e6, 0.1, 20, 20, 150).chamber, ref.chamber);
    EXPECT_LT(d, 0.01 * 0.1e6) << "within 1 % of the 0.1 MPa step";
    EXPECT_LT(d, 0.7 * previous) << "converges as the period halves";
    previous = d;
  }
}

// An outlet volume that is a sliver of the chamber's, through a tube 50x the path's
// conductance, is one gas volume with the chamber: the same step and stretch responses.
TEST(RegulatorLoopTest, OutletSenseTendsToChamberSenseWithAStiffTube) {
  for (RegulatorFeedback feedback : {RegulatorFeedback::kInstant, RegulatorFeedback::kDelayed}) {
    SCOPED_TRACE(regulator_feedback_name(feedback));
    const PneumaticParams chamber = loop_params(feedback, RegulatorSense::kChamber);
    PneumaticParams outlet = loop_params(feedback, RegulatorSense::kOutlet);
    outlet.regulator_outlet_volume_m3 = 0.05e-6;
    outlet.tube_dead_volume_m3 -= outlet.regulator_outlet_volume_m3;  // same total volume
    outlet.tube_conductance_m3_per_s_pa = 50.0 * 1e-3 / kBarToPa;
    const Trace a = run(chamber, 0.5e6, 0.1, 20, 20, 300);
    const Trace b = run(outlet, 0.5e6, 0.1, 20, 20, 300);
    EXPECT_LT(max_difference(a.chamber, b.chamber), 0.01 * 0.1e6);
    EXPECT_LT(max_difference(b.chamber, b.outlet), 0.01 * 0.1e6);
  }
}

// Every combination settles on the command (a proportional valve closed at zero error has
// no offset), with outlet and chamber pressures equal at rest.
TEST(RegulatorLoopTest, EveryLoopSettlesOnTheCommandWithOutletEqualToChamber) {
  for (RegulatorFeedback feedback : {RegulatorFeedback::kInstant, RegulatorFeedback::kDelayed}) {
    for (RegulatorSense sense : {RegulatorSense::kChamber, RegulatorSense::kOutlet}) {
      SCOPED_TRACE(std::string(regulator_feedback_name(feedback)) + "/" +
                   regulator_sense_name(sense));
      const Trace r = run(loop_params(feedback, sense), 0.5e6, 0.05, 20, 40, 2000);
      EXPECT_NEAR(r.chamber.back(), 0.5e6, 10.0);
      EXPECT_NEAR(r.outlet.back(), r.chamber.back(), 1.0);
    }
  }
}

// time [s] at which the chamber first crosses p0 + dp (or p0 - dp) after a step of the
// command far beyond it, with the valve saturating at once (tiny band and lag)
double crossing_time(const PneumaticParams& params, double p0, double p_cmd, double dp) {
  constexpr double kFine = 1e-5;
  PneumaticSystem sys(params, ValveModel::kRegulator, {table_one_braid()}, {p0});
  sys.set_command(0, p_cmd);
  double previous = p0;
  for (int k = 1; k <= 100000; ++k) {
    sys.set_kinematics(0, kLength, 0.0);
    sys.advance(k * kFine);
    const double p = sys.pressure_pa(0);
    if (std::fabs(p - p0) >= dp) {  // interpolate inside the last step
      return (k - 1 + (dp - std::fabs(previous - p0)) / std::fabs(p - previous)) * kFine;
    }
    previous = p;
  }
  return INFINITY;
}

// Choked filling (p / p_supply <= b_s) gives a constant mass flow C_s rho0 p_supply;
// choked venting (p_atm / p <= b_e) one in proportion to p, C_e rho0 p (ISO 6358-1). With
// dp/dt = n R T / V qm at a fixed volume:
//   t_fill = dp / (k C_s p_supply),  t_vent = ln(p0 / (p0 - dp)) / (k C_e),
// k = n R T rho0 sqrt(T0/T) / V; their ratio depends on C_s / C_e and the pressures only.
TEST(RegulatorLoopTest, SeparateSupplyAndExhaustGiveTheChokedFlowRatio) {
  PneumaticParams p = loop_params(RegulatorFeedback::kInstant, RegulatorSense::kChamber);
  p.regulator_dead_time_s = 0.0;
  p.regulator_proportional_band_pa = 100.0;
  p.regulator_valve_time_constant_s = 1e-5;
  p.regulator_supply_conductance_m3_per_s_pa = 0.1e-3 / kBarToPa;
  p.regulator_exhaust_conductance_m3_per_s_pa = 0.05e-3 / kBarToPa;
  p.regulator_supply_critical_ratio = 0.5;
  p.regulator_exhaust_critical_ratio = 0.5;
  const double p0 = 0.2e6, dp = 5e3;  // 301 kPa abs: both paths choked over +-5 kPa
  const double p0_abs = p0 + p.atmospheric_pa, p_supply = p.supply_gauge_pa + p.atmospheric_pa;
  ASSERT_LE((p0_abs + dp) / p_supply, 0.5);
  ASSERT_LE(p.atmospheric_pa / (p0_abs - dp), 0.5);
  const double t_fill = crossing_time(p, p0, 0.3e6, dp);
  const double t_vent = crossing_time(p, p0, 0.1e6, dp);
  const double expected =
      (dp / (*p.regulator_supply_conductance_m3_per_s_pa * p_supply)) /
      (std::log(p0_abs / (p0_abs - dp)) / *p.regulator_exhaust_conductance_m3_per_s_pa);
  EXPECT_NEAR(t_fill / t_vent, expected, 0.01 * expected);
  // and each time itself, at the chamber's volume
  const double volume = chou_hannaford_volume(table_one_braid(), kLength) + p.tube_dead_volume_m3;
  const double k = p.polytropic_index * p.gas_constant_j_per_kg_k * p.temperature_k *
                   kIso6358ReferenceDensityKgM3 *
                   std::sqrt(kIso6358ReferenceTemperatureK / p.temperature_k) / volume;
  EXPECT_NEAR(t_fill, dp / (k * *p.regulator_supply_conductance_m3_per_s_pa * p_supply),
              0.01 * t_fill);
  EXPECT_NEAR(t_vent,
              std::log(p0_abs / (p0_abs - dp)) / (k * *p.regulator_exhaust_conductance_m3_per_s_pa),
              0.01 * t_vent);
}

// Isothermal (n = 1) gas: m = p V / (R T). With the valve shut the tube only moves air
// between outlet and chamber: V_o dp_o/dt + V dp/dt + p dV/dt = 0 in the right-hand side,
// and the total mass stays put while a stretch drives air back into the outlet.
TEST(RegulatorLoopTest, TheTubeConservesMass) {
  PneumaticParams p = loop_params(RegulatorFeedback::kDelayed, RegulatorSense::kOutlet);
  p.polytropic_index = 1.0;
  p.regulator_dead_time_s = 0.2;  // the valve stays shut throughout
  PneumaticOde ode(p, ValveModel::kRegulator, {table_one_braid()});
  ode.set_kinematics(0, 0.0, kLength, 0.2);
  const double y[3] = {0.0, 5e5, 6e5};  // u, chamber, outlet
  double ydot[3];
  ode.rhs(1e-3, y, ydot);
  const double v = ode.volume_m3(0, 1e-3);
  const double balance =
      p.regulator_outlet_volume_m3 * ydot[2] + v * ydot[1] + y[1] * ode.volume_rate_m3_s(0, 1e-3);
  EXPECT_NEAR(balance, 0.0, 1e-12 * v * std::fabs(ydot[1]));
  EXPECT_GT(std::fabs(ydot[2]), 1e3) << "the tube carries air";

  const Trace r = run(p, 0.4e6, 0.1, 10, 50, 100);
  const BraidGeometry g = table_one_braid();
  const auto mass_rt = [&](double chamber, double outlet, double l) {
    const double atm = p.atmospheric_pa;
    return (chamber + atm) * (chou_hannaford_volume(g, l) + p.tube_dead_volume_m3) +
           (outlet + atm) * p.regulator_outlet_volume_m3;
  };
  const double before = mass_rt(0.4e6, 0.4e6, kLength);
  const double after = mass_rt(r.chamber.back(), r.outlet.back(), r.length_end);
  EXPECT_NEAR(after / before, 1.0, 1e-6);
  EXPECT_GT(r.outlet.back() - 0.4e6, 1e3) << "the stretch pushed air into the outlet";
}

TEST(RegulatorLoopTest, TheDelayLineSamplesAndActsOnTime) {
  SampledDelayLine line(0.0, 1e-3, 2.5e-3, {1.0});
  EXPECT_EQ(line.held(), std::vector<double>{1.0});
  EXPECT_DOUBLE_EQ(line.next_sample_s(), 1e-3);
  EXPECT_DOUBLE_EQ(line.next_action_s(), 2.5e-3);
  line.take_sample({2.0});  // at 1 ms, acts at 3.5 ms
  line.take_sample({3.0});  // at 2 ms, acts at 4.5 ms
  EXPECT_DOUBLE_EQ(line.next_event_s(), 2.5e-3);
  EXPECT_FALSE(line.act()) << "the initial sample changes nothing";
  EXPECT_DOUBLE_EQ(line.next_action_s(), 3.5e-3);
  EXPECT_TRUE(line.act());
  EXPECT_EQ(line.held(), std::vector<double>{2.0});
  EXPECT_DOUBLE_EQ(line.next_sample_s(), 3e-3);
}

// solver.on_loop_action: an action of the delayed loop steps the held pressure by what it
// moved in one sample, a small jump every 1 ms. "warm" keeps CVODE's history over it,
// "reinit" restarts CVODE there (order 1, a new Jacobian). On the shipped ITV1000-class loop
// (delayed, outlet, 10 ms / 20 ms / 380 kPa, C = 0.35) at the shipped tolerance, through a
// command step and a stretch, both stay within 1 kPa of a tight reference, and "warm" costs
// a fraction of the right-hand sides (the drop trial: 3 400 against 31 500).
TEST(RegulatorLoopTest, WarmLoopActionsKeepTheAccuracyAtAFractionOfTheCost) {
  PneumaticParams shipped;
  shipped.regulator_feedback = RegulatorFeedback::kDelayed;
  shipped.regulator_sense = RegulatorSense::kOutlet;
  shipped.regulator_dead_time_s = 0.010;
  shipped.regulator_valve_time_constant_s = 0.020;
  shipped.regulator_proportional_band_pa = 380e3;
  shipped.regulator_supply_conductance_m3_per_s_pa = 0.35e-3 / kBarToPa;
  shipped.regulator_exhaust_conductance_m3_per_s_pa = 0.35e-3 / kBarToPa;
  struct Run {
    std::vector<double> chamber;
    long rhs_evals = 0;
  };
  auto run_with = [](PneumaticParams p) {
    PneumaticSystem sys(p, ValveModel::kRegulator, {table_one_braid()}, {0.4e6});
    Run r;
    double l = kLength;
    for (int k = 0; k < 600; ++k) {
      if (k == 50) sys.set_command(0, 0.6e6);
      const double v = (k >= 300 && k < 400) ? 0.05 : 0.0;  // a 5 mm stretch in 0.1 s
      sys.set_kinematics(0, l, v);
      sys.advance((k + 1) * kDt);
      l += v * kDt;
      r.chamber.push_back(sys.pressure_pa(0));
    }
    r.rhs_evals = sys.rhs_evals();
    return r;
  };
  PneumaticParams reference = shipped;
  reference.solver.relative_tolerance = 1e-9;
  reference.solver.absolute_tolerance_pa = 1e-4;
  reference.solver.on_loop_action = CommandChangePolicy::kReinit;
  PneumaticParams warm = shipped, reinit = shipped;
  warm.solver.on_loop_action = CommandChangePolicy::kWarm;
  reinit.solver.on_loop_action = CommandChangePolicy::kReinit;
  const Run ref = run_with(reference), w = run_with(warm), re = run_with(reinit);
  EXPECT_LT(max_difference(w.chamber, ref.chamber), 1e3);
  EXPECT_LT(max_difference(re.chamber, ref.chamber), 1e3);
  EXPECT_LT(3 * w.rhs_evals, re.rhs_evals) << w.rhs_evals << " against " << re.rhs_evals;
  // the stretch was answered: the loop vented after it, the chamber is back near 0.6 MPa
  EXPECT_NEAR(w.chamber.back(), 0.6e6, 5e3);
}

}  // namespace
}  // namespace pamsim
