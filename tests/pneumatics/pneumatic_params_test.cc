// pneumatic_params_test.cc: tests for load_pneumatic_params (models/pams/pneumatics.toml):
// the shipped file, unit conversion, and one bad-value test per key.
#include "pneumatics/pneumatic_params.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <fstream>
#include <string>

#include "base/input_error.h"

namespace pamsim {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
  // ctest runs each test in its own process, in parallel: keep their files apart
  const std::string path = ::testing::TempDir() + std::to_string(::getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}

// the message of the InputError thrown by loading `text`, or "" if none
std::string load_error(const std::string& text) {
  const std::string path = write_temp("pneumatics_bad.toml", text);
  try {
    load_pneumatic_params(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PneumaticParamsTest, ShippedFileLoadsAndConvertsToSi) {
  const PneumaticParams p =
      load_pneumatic_params(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/pneumatics.toml");
  EXPECT_DOUBLE_EQ(p.supply_gauge_pa, 0.7e6);
  EXPECT_DOUBLE_EQ(p.atmospheric_pa, 101325.0);
  EXPECT_DOUBLE_EQ(p.polytropic_index, 1.2);
  EXPECT_NEAR(p.sonic_conductance_m3_per_s_pa, 1e-8, 1e-22);
  EXPECT_DOUBLE_EQ(p.critical_pressure_ratio, 0.3);
  EXPECT_DOUBLE_EQ(p.regulator_time_constant_s, 0.02);
  EXPECT_NEAR(p.tube_dead_volume_m3, 12.566e-6, 1e-15);
  EXPECT_DOUBLE_EQ(p.first_order_time_constant_s, 0.1);
  EXPECT_DOUBLE_EQ(p.command_max_gauge_pa, 0.7e6);
  EXPECT_EQ(p.solver.method, CvodeMethod::kBdf);
  EXPECT_EQ(p.solver.on_command_change, CommandChangePolicy::kReinit);
}

TEST(PneumaticParamsTest, EmptyFileGivesDefaults) {
  const PneumaticParams p = load_pneumatic_params(write_temp("empty.toml", ""));
  EXPECT_DOUBLE_EQ(p.supply_gauge_pa, PneumaticParams{}.supply_gauge_pa);
  EXPECT_NO_THROW(validate_pneumatic_params(PneumaticParams{}, "defaults"));
}

TEST(PneumaticParamsTest, MissingFileNamesThePath) {
  try {
    load_pneumatic_params("/nonexistent/pneumatics.toml");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/pneumatics.toml"), std::string::npos);
  }
}

TEST(PneumaticParamsTest, SyntaxErrorNamesLine) {
  const std::string m = load_error("[valve]\ncritical_pressure_ratio = = 3\n");
  EXPECT_NE(m.find(":2:"), std::string::npos) << m;
}

TEST(PneumaticParamsTest, UnknownTableAndKeyAreNamed) {
  EXPECT_NE(load_error("[valves]\n").find("valves: unknown table"), std::string::npos);
  const std::string m = load_error("[valve]\nsonic_conductance = 1.0\n");
  EXPECT_NE(m.find("valve.sonic_conductance: unknown key"), std::string::npos) << m;
}

struct BadValue {
  const char* table;
  const char* key;
  const char* value;
};

TEST(PneumaticParamsTest, EveryNumericKeyRejectsBadValues) {
  const char* keys[][2] = {
      {"supply", "supply_MPa"},
      {"supply", "atmospheric_kPa"},
      {"gas", "gas_constant_J_per_kg_K"},
      {"gas", "temperature_K"},
      {"gas", "polytropic_index"},
      {"valve", "sonic_conductance_dm3_per_s_bar"},
      {"valve", "critical_pressure_ratio"},
      {"valve", "laminar_ratio"},
      {"valve", "regulator_time_constant_ms"},
      {"valve", "command_min_MPa"},
      {"valve", "command_max_MPa"},
      {"chamber", "tube_dead_volume_cm3"},
      {"first_order", "time_constant_ms"},
      {"regulator", "dead_time_ms"},
      {"regulator", "valve_time_constant_ms"},
      {"regulator", "proportional_band_kPa"},
      {"regulator", "sample_period_ms"},
      {"regulator", "supply_sonic_conductance_dm3_per_s_bar"},
      {"regulator", "supply_critical_pressure_ratio"},
      {"regulator", "exhaust_sonic_conductance_dm3_per_s_bar"},
      {"regulator", "exhaust_critical_pressure_ratio"},
      {"regulator", "outlet_volume_cm3"},
      {"regulator", "tube_sonic_conductance_dm3_per_s_bar"},
      {"regulator", "tube_critical_pressure_ratio"},
      {"solver", "relative_tolerance"},
      {"solver", "absolute_tolerance_Pa"},
  };
  for (const auto& k : keys) {
    for (const char* bad : {"-1.0", "nan", "inf", "\"abc\""}) {
      const std::string text = std::string("[") + k[0] + "]\n" + k[1] + " = " + bad + "\n";
      const std::string m = load_error(text);
      const std::string name = std::string(k[0]) + "." + k[1] + ": ";
      EXPECT_NE(m.find(name), std::string::npos) << "value " << bad << ": " << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
}

// The regulator loop's keys: a conductance must pass air, a ratio stay below the laminar
// ratio, the names be known; the shipped file's loop is delayed and closed on its outlet,
// and a file that leaves the keys out gets the instant loop on the chamber.
TEST(PneumaticParamsTest, RegulatorLoopKeysAreChecked) {
  for (const char* key :
       {"supply_sonic_conductance_dm3_per_s_bar", "exhaust_sonic_conductance_dm3_per_s_bar",
        "tube_sonic_conductance_dm3_per_s_bar", "outlet_volume_cm3", "sample_period_ms"}) {
    const std::string m = load_error(std::string("[regulator]\n") + key + " = 0\n");
    EXPECT_NE(m.find(std::string("pneumatics_bad.toml: regulator.") + key + ": must be in (0, "),
              std::string::npos)
        << m;
  }
  const std::string ratio = load_error(
      "[valve]\nlaminar_ratio = 0.95\n[regulator]\ntube_critical_pressure_ratio = 0.96\n");
  EXPECT_NE(ratio.find("tube critical pressure ratio must be in [0, laminar ratio)"),
            std::string::npos)
      << ratio;
  EXPECT_NE(
      load_error("[regulator]\nfeedback = \"late\"\n")
          .find("regulator.feedback: unknown value \"late\", allowed \"instant\" | \"delayed\""),
      std::string::npos);
  EXPECT_NE(
      load_error("[regulator]\nsense = \"muscle\"\n")
          .find("regulator.sense: unknown value \"muscle\", allowed \"chamber\" | \"outlet\""),
      std::string::npos);
  EXPECT_NE(load_error("[regulator]\nsense = 1\n").find("regulator.sense: must be a string"),
            std::string::npos);

  const PneumaticParams shipped =
      load_pneumatic_params(std::string(PAMSIM_SOURCE_DIR) + "/models/pams/pneumatics.toml");
  // shipped: the ITV1000 class, its loop delayed and closed on its outlet
  EXPECT_EQ(shipped.regulator_feedback, RegulatorFeedback::kDelayed);
  EXPECT_EQ(shipped.regulator_sense, RegulatorSense::kOutlet);
  EXPECT_NEAR(regulator_supply_conductance(shipped), 0.35e-8, 1e-22);
  EXPECT_NEAR(regulator_exhaust_conductance(shipped), 0.35e-8, 1e-22);
  // a file that leaves them out: the instant loop on the chamber, both paths following
  // [valve]
  const PneumaticParams plain = load_pneumatic_params(write_temp("plain.toml", "[regulator]\n"));
  EXPECT_EQ(plain.regulator_feedback, RegulatorFeedback::kInstant);
  EXPECT_EQ(plain.regulator_sense, RegulatorSense::kChamber);
  EXPECT_FALSE(plain.regulator_supply_conductance_m3_per_s_pa.has_value());
  EXPECT_FALSE(plain.regulator_exhaust_conductance_m3_per_s_pa.has_value());
  EXPECT_EQ(regulator_supply_conductance(plain), plain.sonic_conductance_m3_per_s_pa);
  EXPECT_EQ(regulator_exhaust_critical_ratio(plain), plain.critical_pressure_ratio);

  const PneumaticParams p = load_pneumatic_params(write_temp(
      "loop.toml",
      "[regulator]\nfeedback = \"delayed\"\nsense = \"outlet\"\nsample_period_ms = 0.5\n"
      "supply_sonic_conductance_dm3_per_s_bar = 0.35\nexhaust_critical_pressure_ratio = 0.2\n"
      "outlet_volume_cm3 = 3\ntube_sonic_conductance_dm3_per_s_bar = 2\n"));
  EXPECT_EQ(p.regulator_feedback, RegulatorFeedback::kDelayed);
  EXPECT_EQ(p.regulator_sense, RegulatorSense::kOutlet);
  EXPECT_DOUBLE_EQ(p.regulator_sample_period_s, 0.5e-3);
  EXPECT_NEAR(regulator_supply_conductance(p), 0.35e-8, 1e-22);
  EXPECT_EQ(regulator_exhaust_conductance(p), p.sonic_conductance_m3_per_s_pa) << "unset";
  EXPECT_DOUBLE_EQ(regulator_exhaust_critical_ratio(p), 0.2);
  EXPECT_NEAR(p.regulator_outlet_volume_m3, 3e-6, 1e-18);
  EXPECT_NEAR(p.tube_conductance_m3_per_s_pa, 2e-8, 1e-22);
}

TEST(PneumaticParamsTest, PolytropicIndexOutsideOneToOnePointFour) {
  const std::string m = load_error("[gas]\npolytropic_index = 1.5\n");
  EXPECT_NE(m.find("gas.polytropic_index: must be in [1, 1.4], got 1.5"), std::string::npos) << m;
}

TEST(PneumaticParamsTest, CommandRangeMustBeWithinSupply) {
  const std::string m = load_error("[valve]\ncommand_max_MPa = 0.8\n");
  EXPECT_NE(m.find("command range"), std::string::npos) << m;
  EXPECT_NE(load_error("[supply]\nsupply_MPa = 0.5\n").find("command range"), std::string::npos);
}

TEST(PneumaticParamsTest, SolverStringsAreChecked) {
  EXPECT_NE(load_error("[solver]\nmethod = \"rk4\"\n")
                .find("solver.method: unknown value \"rk4\", allowed \"bdf\" | \"adams\""),
            std::string::npos);
  EXPECT_NE(load_error("[solver]\non_command_change = 3\n").find("solver.on_command_change"),
            std::string::npos);
  EXPECT_NE(
      load_error("[solver]\non_loop_action = \"cold\"\n")
          .find("solver.on_loop_action: unknown value \"cold\", allowed \"warm\" | \"reinit\""),
      std::string::npos);
  const PneumaticParams p = load_pneumatic_params(
      write_temp("adams.toml", "[solver]\nmethod = \"adams\"\non_command_change = \"warm\"\n"));
  EXPECT_EQ(p.solver.method, CvodeMethod::kAdams);
  EXPECT_EQ(p.solver.on_command_change, CommandChangePolicy::kWarm);
  EXPECT_EQ(p.solver.on_loop_action, CommandChangePolicy::kReinit);  // unsaid: as before the key
  const PneumaticParams w =
      load_pneumatic_params(write_temp("loop_warm.toml", "[solver]\non_loop_action = \"warm\"\n"));
  EXPECT_EQ(w.solver.on_loop_action, CommandChangePolicy::kWarm);
}

}  // namespace
}  // namespace pamsim
