// chamber_ode_test.cc: tests for the valve + chamber right-hand side (chamber_ode.h):
// the ISO 6358 flow function, equilibrium, the closed-valve polytropic law, input errors.
#include "pneumatics/chamber_ode.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "base/units.h"
#include "pneumatics/pneumatics_test_util.h"

namespace pamsim {
namespace {

using pamsim_test::table_one_braid;

// The valve.model row names the three models as files write them, and reads each name back
// to its model (round trips through the row's setter and getter).
TEST(ChamberOdeTest, TheValveModelRowNamesEachModelAndReadsItBack) {
  ValveModel model = ValveModel::kIso6358;
  const ChoiceRow row = valve_model_row("model", &model);
  EXPECT_EQ(row.allowed, (std::vector<std::string>{"iso6358", "first_order", "regulator"}));
  for (ValveModel m : {ValveModel::kIso6358, ValveModel::kFirstOrder, ValveModel::kRegulator}) {
    row.set(valve_model_name(m));
    EXPECT_EQ(model, m);
    EXPECT_EQ(row.get(), valve_model_name(m));
  }
}

TEST(ChamberOdeTest, FlowFunctionIsChokedEllipticAndLinearNearOne) {
  const double b = 0.3;
  const double r_lam = 0.999;
  EXPECT_EQ(iso6358_flow_function(0.0, b, r_lam), 1.0);
  EXPECT_EQ(iso6358_flow_function(b, b, r_lam), 1.0);
  EXPECT_NEAR(iso6358_flow_function(0.65, b, r_lam), std::sqrt(1.0 - 0.25), 1e-15);
  EXPECT_EQ(iso6358_flow_function(1.0, b, r_lam), 0.0);
  // continuous at r_lam, monotone decreasing, finite slope at 1
  const double at = iso6358_flow_function(r_lam, b, r_lam);
  EXPECT_NEAR(iso6358_flow_function(r_lam + 1e-12, b, r_lam), at, 1e-9);
  double previous = 1.0;
  for (double r = 0.0; r <= 1.0; r += 1e-4) {
    const double psi = iso6358_flow_function(r, b, r_lam);
    EXPECT_LE(psi, previous + 1e-15);
    previous = psi;
  }
  EXPECT_NEAR(iso6358_flow_function(0.9995, b, r_lam), 0.5 * at, 1e-12);
}

TEST(ChamberOdeTest, FirstOrderRhs) {
  PneumaticParams p;
  PneumaticOde ode(p, ValveModel::kFirstOrder, {table_one_braid(), table_one_braid()});
  ASSERT_EQ(ode.size(), 2);
  ode.set_command_abs(0, 3e5);
  ode.set_command_abs(1, 1e5);
  const double y[2] = {2e5, 2e5};
  double ydot[2];
  ode.rhs(0.0, y, ydot);
  EXPECT_DOUBLE_EQ(ydot[0], 1e5 / p.first_order_time_constant_s);
  EXPECT_DOUBLE_EQ(ydot[1], -1e5 / p.first_order_time_constant_s);
}

TEST(ChamberOdeTest, IsoEquilibriumHasZeroDerivative) {
  PneumaticParams p;
  PneumaticOde ode(p, ValveModel::kIso6358, {table_one_braid()});
  ASSERT_EQ(ode.size(), 2);
  const double p_abs = 0.4e6 + p.atmospheric_pa;
  ode.set_command_abs(0, p_abs);
  ode.set_kinematics(0, 0.0, 0.17, 0.0);
  const double y[2] = {p_abs, p_abs};
  double ydot[2];
  ode.rhs(0.0, y, ydot);
  EXPECT_EQ(ydot[0], 0.0);
  EXPECT_EQ(ydot[1], 0.0);
}

TEST(ChamberOdeTest, IsoFlowDirectionAndChokedRate) {
  PneumaticParams p;
  PneumaticOde ode(p, ValveModel::kIso6358, {table_one_braid()});
  const double atm = p.atmospheric_pa;
  ode.set_command_abs(0, atm);
  ode.set_kinematics(0, 0.0, 0.17, 0.0);
  // choked filling: dp/dt = n R T C rho0 sqrt(T0/T) p_reg / V
  double y[2] = {0.7e6 + atm, atm};
  double ydot[2];
  ode.rhs(0.0, y, ydot);
  const double volume = ode.volume_m3(0, 0.0);
  const double expected = p.polytropic_index * p.gas_constant_j_per_kg_k * p.temperature_k *
                          iso6358_mass_flow(p, y[0], y[1]) / volume;
  EXPECT_NEAR(ydot[1], expected, 1e-9 * expected);
  EXPECT_GT(ydot[1], 0.0);
  EXPECT_LT(ydot[0], 0.0);
  // venting through the relief port
  y[0] = atm;
  y[1] = 0.4e6 + atm;
  ode.rhs(0.0, y, ydot);
  EXPECT_LT(ydot[1], 0.0);
}

TEST(ChamberOdeTest, ClosedValveFollowsPolytropicLawRate) {
  // with C = 0: dp/dt = -n p / V dV/dt, i.e. d(p V^n)/dt = 0
  PneumaticParams p;
  p.sonic_conductance_m3_per_s_pa = 0.0;
  PneumaticOde ode(p, ValveModel::kIso6358, {table_one_braid()});
  ode.set_kinematics(0, 1.0, 0.17, -0.05);
  const double y[2] = {2e5, 3e5};
  double ydot[2];
  ode.rhs(1.01, y, ydot);
  const double v = ode.volume_m3(0, 1.01);
  const double vdot = ode.volume_rate_m3_s(0, 1.01);
  EXPECT_NEAR(ydot[1] * v + p.polytropic_index * y[1] * vdot, 0.0, 1e-9);
  // the volume follows the extrapolated length l0 + ldot (t - t0)
  EXPECT_NEAR(v,
              chou_hannaford_volume(table_one_braid(), 0.17 - 0.05 * 0.01) + p.tube_dead_volume_m3,
              1e-15);
}

TEST(ChamberOdeTest, NonPhysicalTrialStateIsRecoverable) {
  PneumaticOde ode(PneumaticParams{}, ValveModel::kIso6358, {table_one_braid()});
  ode.set_kinematics(0, 0.0, 0.17, 0.0);
  const double y[2] = {2e5, -1.0};
  double ydot[2];
  EXPECT_THROW(ode.rhs(0.0, y, ydot), RecoverableRhsError);
}

TEST(ChamberOdeTest, RejectsBadConstruction) {
  EXPECT_THROW(PneumaticOde(PneumaticParams{}, ValveModel::kIso6358, {}), InputError);
  PneumaticParams bad;
  bad.polytropic_index = 2.0;
  EXPECT_THROW(PneumaticOde(bad, ValveModel::kIso6358, {table_one_braid()}), InputError);
}

// A physical muscle's chamber is the AVBDL shape's (less than Chou-Hannaford's cylinder once
// contracted: the end regions), and its rate follows the length's.
TEST(ChamberOdeTest, APlantsChamberHasItsAvbdlVolume) {
  const AvbdlParams plant = avbdl_params_from_geometry(0.18, 0.010, units::deg_to_rad(25.0), 0.002,
                                                       kNaturalRubberTreloar);
  const PneumaticParams params;
  PneumaticOde ode(params, ValveModel::kIso6358, {avbdl_braid(plant), avbdl_braid(plant)});
  ode.set_plant_volume(1, plant);
  ode.set_kinematics(0, 0.0, 0.150, -0.02);
  ode.set_kinematics(1, 0.0, 0.150, -0.02);
  const double dead = params.tube_dead_volume_m3;
  EXPECT_DOUBLE_EQ(ode.volume_m3(0, 0.0), chou_hannaford_volume(avbdl_braid(plant), 0.150) + dead);
  EXPECT_DOUBLE_EQ(ode.volume_m3(1, 0.0), avbdl_volume(plant, 0.150) + dead);
  EXPECT_LT(ode.volume_m3(1, 0.0), ode.volume_m3(0, 0.0));
  const double l = 0.150 + -0.02 * 0.5;  // 0.5 s later, extrapolated as the ODE does
  EXPECT_DOUBLE_EQ(ode.volume_m3(1, 0.5), avbdl_volume(plant, l) + dead);
  EXPECT_DOUBLE_EQ(ode.volume_rate_m3_s(1, 0.5), avbdl_dvolume_dlength(plant, l) * -0.02);
  EXPECT_THROW(ode.set_plant_volume(2, plant), std::out_of_range);
}

// Each muscle's derivatives depend on its own states alone, in a block of
// states_per_muscle() (what the banded Jacobian of cvode_integrator.cc relies on): moving
// one state moves no other muscle's derivative by a bit, for every valve model and sensing
TEST(ChamberOdeTest, EachMuscleIsABlockOfItsOwnStates) {
  struct Case {
    ValveModel model;
    RegulatorSense sense;
    int states;
  };
  for (const Case& c : {Case{ValveModel::kFirstOrder, RegulatorSense::kChamber, 1},
                        Case{ValveModel::kIso6358, RegulatorSense::kChamber, 2},
                        Case{ValveModel::kRegulator, RegulatorSense::kChamber, 2},
                        Case{ValveModel::kRegulator, RegulatorSense::kOutlet, 3}}) {
    PneumaticParams params;
    params.regulator_sense = c.sense;
    PneumaticOde ode(params, c.model, {table_one_braid(), table_one_braid(), table_one_braid()});
    ASSERT_EQ(ode.states_per_muscle(), c.states);
    ASSERT_EQ(ode.half_bandwidth(), c.states - 1);
    std::vector<double> y(ode.size());
    for (int i = 0; i < ode.muscle_count(); ++i) {
      ode.set_command_abs(i, (3.0 + i) * 1e5);
      ode.set_sensed_abs(i, (2.5 + i) * 1e5);
      ode.set_kinematics(i, 0.0, 0.16 + 0.005 * i, 0.01 * (i - 1));
      for (int k = 0; k < c.states; ++k) y[c.states * i + k] = (2.0 + 0.5 * i + 0.1 * k) * 1e5;
      if (ode.valve_opening_index(i) >= 0) y[ode.valve_opening_index(i)] = 0.2 * (i - 1);
    }
    std::vector<double> base(ode.size()), moved(ode.size());
    ode.rhs(0.0, y.data(), base.data());
    for (int j = 0; j < ode.size(); ++j) {
      std::vector<double> z = y;
      z[j] += 0.01 * std::max(std::fabs(z[j]), 1.0);
      ode.rhs(0.0, z.data(), moved.data());
      for (int i = 0; i < ode.size(); ++i) {
        if (i / c.states == j / c.states) continue;
        ASSERT_EQ(moved[i], base[i])
            << valve_model_name(c.model) << ": state " << j << " moved derivative " << i;
      }
    }
  }
}

}  // namespace
}  // namespace pamsim
