// regulator_test.cc: the "regulator" valve model (chamber_ode.h, pneumatics.h): the command
// reaches the valve exactly one dead time late, the step settles on the command without
// offset and more slowly with a slower valve, a closed chamber under a stretch follows the
// isothermal p V = const, and a stretch raises the pressure of a regulated chamber more than
// the ideal-source model ("iso6358") lets it, and less than a closed chamber.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "pneumatics/pneumatics.h"
#include "base/units.h"
#include "pneumatics/pneumatics_test_util.h"

namespace pamsim {
namespace {

using pamsim_test::kDt;
using pamsim_test::kLength;
using pamsim_test::table_one_braid;

// p(t) [Pa gauge] after each of n physics steps at fixed length, a step to p_cmd at t = 0
std::vector<double> step_response(const PneumaticParams& params, double p0, double p_cmd, int n) {
  PneumaticSystem sys(params, ValveModel::kRegulator, {table_one_braid()}, {p0});
  sys.set_command(0, p_cmd);
  std::vector<double> p;
  for (int k = 1; k <= n; ++k) {
    sys.set_kinematics(0, kLength, 0.0);
    sys.advance(k * kDt);
    p.push_back(sys.pressure_pa(0));
  }
  return p;
}

TEST(RegulatorTest, CommandArrivesExactlyOneDeadTimeLate) {
  for (double dead_ms : {0.0, 2.0, 5.0, 10.0}) {
    SCOPED_TRACE(dead_ms);
    PneumaticParams params;
    params.regulator_dead_time_s = dead_ms * 1e-3;
    const std::vector<double> p = step_response(params, 0.4e6, 0.5e6, 40);
    for (int k = 1; k <= 40; ++k) {
      const double t_ms = k;  // p[k - 1] is at t = k ms
      if (t_ms <= dead_ms) {
        EXPECT_EQ(p[k - 1], 0.4e6) << "t = " << t_ms << " ms: still at rest";
      } else if (t_ms >= dead_ms + 3.0) {
        EXPECT_GT(p[k - 1], 0.4e6 + 1e3) << "t = " << t_ms << " ms: rising";
      }
    }
  }
}

// A dead time that ends inside a physics step splits the step there: at rest up to 2 ms,
// already moving at 3 ms, with either solver policy at a command change.
TEST(RegulatorTest, ADeadTimeInsideAStepTakesEffectThere) {
  for (CommandChangePolicy policy : {CommandChangePolicy::kReinit, CommandChangePolicy::kWarm}) {
    PneumaticParams params;
    params.regulator_dead_time_s = 2.5e-3;
    params.solver.on_command_change = policy;
    const std::vector<double> p = step_response(params, 0.4e6, 0.5e6, 5);
    EXPECT_EQ(p[1], 0.4e6) << "t = 2 ms";
    EXPECT_GT(p[2], 0.4e6) << "t = 3 ms";
  }
}

// 10-90 % rise time [s] of a 0.4 -> 0.5 MPa step
double rise_time(const PneumaticParams& params) {
  const std::vector<double> p = step_response(params, 0.4e6, 0.5e6, 300);
  double t10 = NAN, t90 = NAN;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (std::isnan(t10) && p[k] >= 0.41e6) t10 = (k + 1) * kDt;
    if (std::isnan(t90) && p[k] >= 0.49e6) t90 = (k + 1) * kDt;
  }
  return t90 - t10;
}

TEST(RegulatorTest, StepSettlesOnTheCommandAndSlowsWithTheValve) {
  double previous = 0.0;
  for (double valve_ms : {5.0, 10.0, 20.0}) {
    SCOPED_TRACE(valve_ms);
    PneumaticParams params;
    params.regulator_valve_time_constant_s = valve_ms * 1e-3;
    const std::vector<double> p = step_response(params, 0.4e6, 0.5e6, 300);
    EXPECT_NEAR(p.back(), 0.5e6, 100.0) << "no steady offset";
    EXPECT_LT(*std::max_element(p.begin(), p.end()), 0.5e6 + 0.5 * 0.1e6);
    const double rise = rise_time(params);
    EXPECT_GT(rise, previous);
    EXPECT_LT(rise, 0.1) << "the catalogue class settles in 0.1 s";
    previous = rise;
  }
}

// a stretch of the muscle at `velocity` for n steps after 50 steps at rest; returns the
// largest and the final pressure rise [Pa], and the isothermal closed-chamber rise
struct StretchRise {
  double peak = 0.0, final = 0.0, closed_isothermal = 0.0;
};
StretchRise stretch(const PneumaticParams& params, ValveModel model, double velocity, int n) {
  PneumaticSystem sys(params, model, {table_one_braid()}, {0.4e6});
  for (int k = 1; k <= 50; ++k) {
    sys.set_kinematics(0, kLength, 0.0);
    sys.advance(k * kDt);
  }
  const double p0 = sys.pressure_pa(0);
  StretchRise r;
  double l = kLength;
  for (int k = 0; k < n; ++k) {
    sys.set_kinematics(0, l, velocity);
    sys.advance(sys.time_s() + kDt);
    l += velocity * kDt;
    r.peak = std::max(r.peak, sys.pressure_pa(0) - p0);
  }
  r.final = sys.pressure_pa(0) - p0;
  const BraidGeometry g = table_one_braid();
  const double v0 = chou_hannaford_volume(g, kLength) + params.tube_dead_volume_m3;
  const double v1 = chou_hannaford_volume(g, l) + params.tube_dead_volume_m3;
  r.closed_isothermal = (p0 + params.atmospheric_pa) * (v0 / v1 - 1.0);
  return r;
}

TEST(RegulatorTest, ClosedChamberUnderAStretchIsIsothermalBoyle) {
  PneumaticParams params;
  params.sonic_conductance_m3_per_s_pa = 0.0;  // closed valve
  params.polytropic_index = 1.0;               // isothermal
  for (ValveModel model : {ValveModel::kIso6358, ValveModel::kRegulator}) {
    SCOPED_TRACE(valve_model_name(model));
    const StretchRise r = stretch(params, model, 0.1, 20);  // 2 mm at 100 mm/s
    EXPECT_GT(r.closed_isothermal, 5e3);
    EXPECT_NEAR(r.final, r.closed_isothermal, 1e-3 * r.closed_isothermal);
  }
}

TEST(RegulatorTest, AStretchRaisesTheRegulatedChamberMoreThanAnIdealSource) {
  // the impact's stretch: 2 mm at 100 mm/s
  const PneumaticParams params;
  const StretchRise ideal = stretch(params, ValveModel::kIso6358, 0.1, 20);
  const StretchRise regulated = stretch(params, ValveModel::kRegulator, 0.1, 20);
  EXPECT_LT(ideal.peak, 0.2 * ideal.closed_isothermal);
  EXPECT_GT(regulated.peak, 2.0 * ideal.peak);
  EXPECT_LT(regulated.peak, regulated.closed_isothermal);
}

TEST(RegulatorTest, BadRegulatorParametersAreNamed) {
  struct Case {
    double PneumaticParams::*field;
    double value;
    const char* says;
  };
  const Case cases[] = {
      {&PneumaticParams::regulator_dead_time_s, -1e-3, "regulator dead time"},
      {&PneumaticParams::regulator_dead_time_s, NAN, "regulator dead time"},
      {&PneumaticParams::regulator_valve_time_constant_s, 0.0, "regulator valve time constant"},
      {&PneumaticParams::regulator_proportional_band_pa, -5.0, "regulator proportional band"},
      {&PneumaticParams::regulator_proportional_band_pa, INFINITY, "regulator proportional band"},
      {&PneumaticParams::regulator_sample_period_s, 0.0, "regulator sample period"},
      {&PneumaticParams::regulator_sample_period_s, NAN, "regulator sample period"},
      {&PneumaticParams::regulator_outlet_volume_m3, -1e-6, "regulator outlet volume"},
      {&PneumaticParams::tube_conductance_m3_per_s_pa, 0.0, "tube sonic conductance"},
      {&PneumaticParams::tube_conductance_m3_per_s_pa, NAN, "tube sonic conductance"},
      {&PneumaticParams::tube_critical_ratio, 1.0, "tube critical pressure ratio"},
  };
  for (const Case& c : cases) {
    PneumaticParams params;
    params.*c.field = c.value;
    try {
      validate_pneumatic_params(params, "pneumatics.toml");
      ADD_FAILURE() << c.says << " = " << c.value << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("pneumatics.toml: ") + c.says),
                std::string::npos)
          << e.what();
    }
  }
}

// an optional restriction, once given, must pass air: C > 0, b below the laminar ratio
TEST(RegulatorTest, BadSupplyAndExhaustRestrictionsAreNamed) {
  const auto error_of = [](const PneumaticParams& params) -> std::string {
    try {
      validate_pneumatic_params(params, "pneumatics.toml");
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  PneumaticParams p;
  p.regulator_supply_conductance_m3_per_s_pa = 0.0;
  EXPECT_NE(error_of(p).find("pneumatics.toml: regulator supply sonic conductance must be > 0"),
            std::string::npos);
  p = PneumaticParams{};
  p.regulator_exhaust_conductance_m3_per_s_pa = NAN;
  EXPECT_NE(error_of(p).find("pneumatics.toml: regulator exhaust sonic conductance"),
            std::string::npos);
  p = PneumaticParams{};
  p.regulator_exhaust_critical_ratio = -0.1;
  EXPECT_NE(error_of(p).find("pneumatics.toml: regulator exhaust critical pressure ratio"),
            std::string::npos);
  // unset, they follow [valve], whose C may be 0 (a shut valve, as before)
  p = PneumaticParams{};
  p.sonic_conductance_m3_per_s_pa = 0.0;
  EXPECT_EQ(error_of(p), "");
}

// The shipped regulator is the bracket's slow end, the ITV1000 class (pneumatics.toml).
TEST(RegulatorTest, TheShippedFileGivesTheItv1000BracketValues) {
  const PneumaticParams p =
      load_pneumatic_params(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/pneumatics.toml");
  EXPECT_DOUBLE_EQ(p.regulator_dead_time_s, 0.010);
  EXPECT_DOUBLE_EQ(p.regulator_valve_time_constant_s, 0.020);
  EXPECT_DOUBLE_EQ(p.regulator_proportional_band_pa, 380e3);
}

}  // namespace
}  // namespace pamsim
