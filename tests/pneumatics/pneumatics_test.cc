// pneumatics_test.cc: tests for PneumaticSystem (pneumatics.h): the first-order valve
// against its analytic step response, the ISO 6358 step's rise time and pressure bounds,
// the closed-valve polytropic invariant, equilibrium, accuracy against a tight-tolerance
// reference, determinism and input errors.
#include "pneumatics/pneumatics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "base/input_error.h"
#include "base/units.h"
#include "pneumatics/pneumatics_test_util.h"

namespace pamsim {
namespace {

using pamsim_test::kDt;
using pamsim_test::kL0;
using pamsim_test::table_one_braid;

// runs n physics steps at fixed length l for every muscle
void run_fixed_length(PneumaticSystem& sys, int n, double l) {
  for (int k = 0; k < n; ++k) {
    for (int i = 0; i < sys.muscle_count(); ++i) sys.set_kinematics(i, l, 0.0);
    sys.advance(sys.time_s() + kDt);
  }
}

TEST(PneumaticsTest, FirstOrderMatchesAnalyticStepResponse) {
  // p(t) = p_cmd + (p0 - p_cmd) exp(-t / tau); agreement to 1e-6 of the step (0.4 Pa) at
  // rtol 1e-8 (the default tolerances' error is bounded by the accuracy test below)
  PneumaticParams params;
  params.solver.relative_tolerance = 1e-8;
  params.solver.absolute_tolerance_pa = 1e-3;
  const double tau = params.first_order_time_constant_s;
  const double p0 = 0.1e6;
  const double p_cmd = 0.5e6;
  PneumaticSystem sys(params, ValveModel::kFirstOrder, {table_one_braid()}, {p0});
  sys.set_command(0, p_cmd);
  double worst = 0.0;
  for (int k = 1; k <= 1000; ++k) {
    sys.set_kinematics(0, 0.17, 0.0);
    sys.advance(k * kDt);
    const double exact = p_cmd + (p0 - p_cmd) * std::exp(-sys.time_s() / tau);
    worst = std::max(worst, std::abs(sys.pressure_pa(0) - exact) / (p_cmd - p0));
  }
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(sys.regulator_pressure_pa(0), p_cmd);
}

// 10-90 % rise time [s] of a 0 -> target step with the ISO 6358 valve; also records the
// pressure range seen
double iso_rise_time(const PneumaticParams& params, double target, double* p_min, double* p_max) {
  PneumaticSystem sys(params, ValveModel::kIso6358, {table_one_braid()}, {0.0});
  sys.set_command(0, target);
  double t10 = -1.0;
  double t90 = -1.0;
  *p_min = 0.0;
  *p_max = 0.0;
  for (int k = 1; k <= 2000; ++k) {
    sys.set_kinematics(0, 0.17, 0.0);
    sys.advance(k * kDt);
    const double p = sys.pressure_pa(0);
    *p_min = std::min(*p_min, p);
    *p_max = std::max(*p_max, p);
    if (t10 < 0.0 && p >= 0.1 * target) t10 = sys.time_s();
    if (t90 < 0.0 && p >= 0.9 * target) t90 = sys.time_s();
  }
  return t90 - t10;
}

TEST(PneumaticsTest, IsoStepRiseTimeIsRealisticAndPressureBounded) {
  // Realistic range 20-300 ms: the regulator class alone settles in <= 0.1 s (SMC ITV
  // catalogue, "response time 0.1 s or less", no load) and the choked fill of ~45 cm^3
  // through C = 1 dm^3/(s bar) from 0.5 MPa abs takes dp/(n R T C rho0 p_up / V) ~ 30 ms
  // for 0.4 MPa; PAM step responses of 0.05-0.3 s are what the issue asks for ("tens to a
  // few hundred ms"). Measured here (1 ms physics steps): see the printed value.
  const PneumaticParams params;
  double p_min = 0.0;
  double p_max = 0.0;
  const double rise = iso_rise_time(params, 0.4e6, &p_min, &p_max);
  RecordProperty("rise_time_ms", std::to_string(rise * 1e3));
  std::printf("ISO 6358 0 -> 0.4 MPa rise time (10-90 %%): %.1f ms\n", rise * 1e3);
  EXPECT_GE(rise, 0.020);
  EXPECT_LE(rise, 0.300);
  EXPECT_GE(p_min, 0.0);
  EXPECT_LE(p_max, params.supply_gauge_pa);
  EXPECT_LE(p_max, 0.4e6 + 1.0);  // a first-order regulator does not overshoot
}

TEST(PneumaticsTest, IsoPressureStaysWithinSupplyUnderFastLengthChanges) {
  // 5 Hz, +/-8 mm length oscillation (0.25 m/s peak) while the command jumps between
  // 0.05 and the full supply every 50 ms
  const PneumaticParams params;
  PneumaticSystem sys(params, ValveModel::kIso6358, {table_one_braid(), table_one_braid()},
                      {0.0, 0.4e6});
  const double w = 2.0 * units::kPi * 5.0;
  double p_min = 1e9;
  double p_max = -1e9;
  for (int k = 0; k < 2000; ++k) {
    const double t = sys.time_s();
    if (k % 50 == 0) {
      const bool high = (k / 50) % 2 == 0;
      sys.set_command(0, high ? 0.7e6 : 0.05e6);
      sys.set_command(1, high ? 0.05e6 : 0.7e6);
    }
    for (int i = 0; i < 2; ++i) {
      const double phase = i == 0 ? 0.0 : units::kPi;
      sys.set_kinematics(i, 0.165 + 0.008 * std::sin(w * t + phase),
                         0.008 * w * std::cos(w * t + phase));
    }
    sys.advance(t + kDt);
    for (int i = 0; i < 2; ++i) {
      p_min = std::min(p_min, sys.pressure_pa(i));
      p_max = std::max(p_max, sys.pressure_pa(i));
      ASSERT_GE(sys.regulator_pressure_pa(i), -1e-6);
      ASSERT_LE(sys.regulator_pressure_pa(i), params.supply_gauge_pa + 1e-6);
    }
  }
  std::printf("pressure range under 5 Hz length oscillation: [%.1f, %.1f] kPa\n", p_min * 1e-3,
              p_max * 1e-3);
  EXPECT_GE(p_min, 0.0);
  EXPECT_LE(p_max, params.supply_gauge_pa);
}

TEST(PneumaticsTest, ClosedValveKeepsPolytropicInvariant) {
  // C = 0 and a constant-velocity shortening: p V^n is constant (mass conservation with
  // the polytropic law), up to the solver tolerance
  PneumaticParams params;
  params.sonic_conductance_m3_per_s_pa = 0.0;
  params.solver.relative_tolerance = 1e-8;
  params.solver.absolute_tolerance_pa = 1e-4;
  const double v_dead = params.tube_dead_volume_m3;
  const BraidGeometry braid = table_one_braid();
  PneumaticSystem sys(params, ValveModel::kIso6358, {braid}, {0.3e6});
  auto invariant = [&](double l) {
    const double p_abs = sys.pressure_pa(0) + params.atmospheric_pa;
    return p_abs * std::pow(chou_hannaford_volume(braid, l) + v_dead, params.polytropic_index);
  };
  const double velocity = -0.02;  // 20 mm/s shortening
  const double c0 = invariant(0.175);
  double worst = 0.0;
  for (int k = 0; k < 500; ++k) {
    const double l = 0.175 + velocity * sys.time_s();
    sys.set_kinematics(0, l, velocity);
    sys.advance(sys.time_s() + kDt);
    worst = std::max(worst, std::abs(invariant(0.175 + velocity * sys.time_s()) / c0 - 1.0));
  }
  EXPECT_LT(worst, 1e-6);
  // above l = b / sqrt(3) the Chou-Hannaford volume grows as the muscle shortens
  EXPECT_LT(sys.pressure_pa(0), 0.3e6);
}

TEST(PneumaticsTest, HeldCommandConvergesToCommand) {
  for (ValveModel model : {ValveModel::kIso6358, ValveModel::kFirstOrder}) {
    PneumaticSystem sys(PneumaticParams{}, model, {table_one_braid()}, {0.0});
    sys.set_command(0, 0.3e6);
    run_fixed_length(sys, 2000, 0.17);
    EXPECT_NEAR(sys.pressure_pa(0), 0.3e6, 1.0) << valve_model_name(model);
    EXPECT_NEAR(sys.regulator_pressure_pa(0), 0.3e6, 1.0);
  }
}

TEST(PneumaticsTest, CommandIsClampedToValveRange) {
  PneumaticSystem sys(PneumaticParams{}, ValveModel::kIso6358, {table_one_braid()}, {0.0});
  sys.set_command(0, 2e6);
  EXPECT_EQ(sys.command_pa(0), 0.7e6);
  sys.set_command(0, -5.0);
  EXPECT_EQ(sys.command_pa(0), 0.0);
  EXPECT_THROW(sys.set_command(0, std::nan("")), std::invalid_argument);
  EXPECT_THROW(sys.set_command(1, 0.1e6), std::out_of_range);
}

// a 100 Hz controller and a moving arm: commands and lengths change every step
std::vector<double> scenario_trace(const PneumaticParams& params, ValveModel model) {
  PneumaticSystem sys(params, model, {table_one_braid(), table_one_braid()}, {0.4e6, 0.4e6});
  std::vector<double> trace;
  const double w = 2.0 * units::kPi * 3.0;
  for (int k = 0; k < 1500; ++k) {
    const double t = sys.time_s();
    if (k % 10 == 0) {
      sys.set_command(
          0, 0.4e6 + 0.15e6 * std::sin(2.0 * units::kPi * t) + (k % 200 < 20 ? 0.1e6 : 0.0));
      sys.set_command(1, 0.4e6 - 0.15e6 * std::sin(2.0 * units::kPi * t));
    }
    sys.set_kinematics(0, 0.165 + 0.005 * std::sin(w * t), 0.005 * w * std::cos(w * t));
    sys.set_kinematics(1, 0.165 - 0.005 * std::sin(w * t), -0.005 * w * std::cos(w * t));
    sys.advance(t + kDt);
    trace.push_back(sys.pressure_pa(0));
    trace.push_back(sys.pressure_pa(1));
  }
  return trace;
}

TEST(PneumaticsTest, DefaultTolerancesAreAccurateToWellUnderOneKilopascal) {
  PneumaticParams reference_params;
  reference_params.solver.relative_tolerance = 1e-9;
  reference_params.solver.absolute_tolerance_pa = 1e-4;
  // the reference restarts at every command change (a jump in dp_reg/dt); warm restarts at
  // tight tolerances need tiny steps to pass the error test at such jumps
  reference_params.solver.on_command_change = CommandChangePolicy::kReinit;
  for (ValveModel model : {ValveModel::kIso6358, ValveModel::kFirstOrder}) {
    const std::vector<double> reference = scenario_trace(reference_params, model);
    for (CommandChangePolicy policy : {CommandChangePolicy::kWarm, CommandChangePolicy::kReinit}) {
      PneumaticParams params;
      params.solver.on_command_change = policy;
      const std::vector<double> trace = scenario_trace(params, model);
      double worst = 0.0;
      for (std::size_t k = 0; k < trace.size(); ++k) {
        worst = std::max(worst, std::abs(trace[k] - reference[k]));
      }
      std::printf("%s, %s: max pressure error %.3f Pa\n", valve_model_name(model),
                  policy == CommandChangePolicy::kWarm ? "warm" : "reinit", worst);
      // default (reinit) well under 1 kPa; warm restarts trade accuracy for speed
      EXPECT_LT(worst, policy == CommandChangePolicy::kReinit ? 300.0 : 1000.0);
    }
  }
}

TEST(PneumaticsTest, RunsAreBitIdentical) {
  for (ValveModel model : {ValveModel::kIso6358, ValveModel::kFirstOrder}) {
    EXPECT_EQ(scenario_trace(PneumaticParams{}, model), scenario_trace(PneumaticParams{}, model));
  }
}

TEST(PneumaticsTest, RejectsBadInputs) {
  const PneumaticParams params;
  EXPECT_THROW(PneumaticSystem(params, ValveModel::kIso6358, {table_one_braid()}, {0.8e6}),
               InputError);
  EXPECT_THROW(PneumaticSystem(params, ValveModel::kIso6358, {table_one_braid()}, {}), InputError);
  PneumaticSystem sys(params, ValveModel::kIso6358, {table_one_braid()}, {0.0});
  EXPECT_THROW(sys.advance(kDt), std::logic_error);                      // kinematics never set
  EXPECT_THROW(sys.set_kinematics(0, 0.5, 0.0), std::invalid_argument);  // > fibre length
  EXPECT_THROW(sys.set_kinematics(0, 0.17, std::nan("")), std::invalid_argument);
  sys.set_kinematics(0, 0.17, 0.0);
  sys.advance(kDt);
  EXPECT_THROW(sys.advance(0.0), IntegrationError);  // backwards in time
}

}  // namespace
}  // namespace pamsim
