// stretch_reflex_config_test.cc: the StretchReflexController's configuration: the defaults
// are valid, a bad-value test for every validated key (the message names the key and quotes
// the value, and says what is allowed), the reflex sensor's names and Table II's values.
#include "reflex/stretch_reflex_controller.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stretch_reflex_harness.h"

#include "base/input_error.h"
#include "base/no_value.h"

namespace pamsim {
namespace {

using reflex_test::two_pairs;
using test::expect_bad_value;
using BadValue = test::BadValueOf<StretchReflexControllerConfig>;

// --- bad values: every validated key; the message names the key and quotes the value ---

using BadValue = test::BadValueOf<StretchReflexControllerConfig>;

// clang-format off
std::vector<BadValue> bad_values() {
  using C = StretchReflexControllerConfig&;
  return {
      {"sim.control_hz", "0", [](C c) { c.control_hz = 0.0; }},
      {"sim.control_hz", "nan", [](C c) { c.control_hz = kNaN; }},
      // an enum outside its names reads as "?"
      {"reflex.sensor", "\"?\"", [](C c) { c.reflex.sensor = static_cast<ReflexSensor>(7); }},
      {"reflex.mode", "\"?\"", [](C c) { c.reflex.mode = static_cast<ReflexMode>(7); }},
      // SI fields, reported in the keys' units
      {"reflex.v_thr_mm_s", "-5", [](C c) { c.reflex.v_thr_m_s = -0.005; }},
      {"reflex.v_thr_mm_s", "0", [](C c) { c.reflex.v_thr_m_s = 0.0; }},
      {"reflex.v_thr_mm_s", "nan", [](C c) { c.reflex.v_thr_m_s = kNaN; }},
      {"reflex.k_MPa_s_per_mm", "-0.001", [](C c) { c.reflex.k_pa_s_per_m = -1e6; }},
      {"reflex.k_MPa_s_per_mm", "nan", [](C c) { c.reflex.k_pa_s_per_m = kNaN; }},
      {"reflex.duration_s", "-0.2", [](C c) { c.reflex.duration_s = -0.2; }},
      {"reflex.duration_s", "0.001", [](C c) { c.reflex.duration_s = 0.001; }},
      {"reflex.duration_s", "nan", [](C c) { c.reflex.duration_s = kNaN; }},
      // one control period is 20 ms at 50 Hz
      {"reflex.duration_s", "0.01", [](C c) { c.control_hz = 50.0; c.reflex.duration_s = 0.01; }},
      {"reflex.refractory_s", "-0.1", [](C c) { c.reflex.refractory_s = -0.1; }},
      {"reflex.refractory_s", "nan", [](C c) { c.reflex.refractory_s = kNaN; }},
      {"reflex.refractory_s", "1e+10", [](C c) { c.reflex.refractory_s = 1e10; }},
      {"reflex.duration_s", "1e+10", [](C c) { c.reflex.duration_s = 1e10; }},
      {"reflex.arm_after_s", "-1", [](C c) { c.reflex.arm_after_s = -1.0; }},
      {"reflex.arm_after_s", "nan", [](C c) { c.reflex.arm_after_s = kNaN; }},
      {"reflex.min_tension_N", "-1", [](C c) { c.reflex.min_tension_n = -1.0; }},
      {"reflex.min_tension_N", "nan", [](C c) { c.reflex.min_tension_n = kNaN; }},
      // in MPa, as in the scenario file
      {"controller.p_max_MPa", "0", [](C c) { c.p_max_pa = 0.0; }},
      {"controller.p_max_MPa", "-0.1", [](C c) { c.p_max_pa = -0.1e6; }},
      {"controller.p_max_MPa", "nan", [](C c) { c.p_max_pa = kNaN; }},
      // reflex.pairs: an index out of range
      {"reflex.pairs[0]", "-1", [](C c) { c.pairs = {ReflexPair{-1, 1}}; }},
      {"reflex.pairs[0]", "2", [](C c) { c.pairs = {ReflexPair{0, 2}}; }},
      {"reflex.pairs[0]", "0", [](C c) { c.muscle_count = 0; }},
      {"reflex.pairs[1]", "4",
       [](C c) { c.muscle_count = 4; c.pairs = {ReflexPair{0, 1}, ReflexPair{4, 2}}; }},
      // a muscle in two pairs, as agonist or antagonist
      {"reflex.pairs[1]", "1",
       [](C c) { c.muscle_count = 4; c.pairs = {ReflexPair{0, 1}, ReflexPair{1, 2}}; }},
      {"reflex.pairs[1]", "0",
       [](C c) { c.muscle_count = 4; c.pairs = {ReflexPair{0, 1}, ReflexPair{2, 0}}; }},
      // a muscle paired with itself
      {"reflex.pairs[0]", "1", [](C c) { c.pairs = {ReflexPair{1, 1}}; }},
  };
}
// clang-format on

TEST(StretchReflexControllerConfig, DefaultsAreValid) {
  StretchReflexControllerConfig config;
  EXPECT_NO_THROW(validate(config));
  config.reflex = table_ii_reflex_config(ReflexSensor::kFiber);
  EXPECT_NO_THROW(validate(config));
  // no pair at all; two pairs of four; a pair that skips a muscle
  config.pairs.clear();
  EXPECT_NO_THROW(validate(config));
  EXPECT_NO_THROW(validate(two_pairs().controller));
  config.muscle_count = 3;
  config.pairs = {ReflexPair{2, 0}};
  EXPECT_NO_THROW(validate(config));
}

TEST(StretchReflexControllerConfig, EveryBadValueThrowsNamingTheKeyAndValue) {
  for (const BadValue& bad : bad_values()) {
    SCOPED_TRACE(bad.key + " = " + bad.value);
    StretchReflexControllerConfig config;
    bad.set(config);
    expect_bad_value([&] { validate(config); }, bad.key, bad.value);
    // the constructor validates too
    expect_bad_value([&] { StretchReflexController{config}; }, bad.key, bad.value);
  }
}

TEST(StretchReflexControllerConfig, MessagesSayWhatIsAllowed) {
  auto message = [](const std::function<void(StretchReflexControllerConfig&)>& set) {
    StretchReflexControllerConfig config;
    set(config);
    try {
      validate(config);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  using C = StretchReflexControllerConfig&;
  EXPECT_EQ(message([](C c) { c.reflex.v_thr_m_s = -0.005; }),
            "reflex.v_thr_mm_s must be in (0, inf), got -5");
  EXPECT_EQ(message([](C c) { c.reflex.duration_s = 0.001; }),
            "reflex.duration_s must be >= one control period (0.01 s), got 0.001");
  EXPECT_EQ(message([](C c) {
              c.pairs = {ReflexPair{0, 2}};
            }),
            "reflex.pairs[0] must be a muscle index in [0, 2), got 2");
  EXPECT_EQ(message([](C c) {
              c.muscle_count = 3;
              c.pairs = {{0, 1}, {2, 1}};
            }),
            "reflex.pairs[1] must be muscles not already in a pair (muscle index), got 1");
}

TEST(ReflexSensor, ParsesAndRejectsNamingTheKey) {
  EXPECT_EQ(parse_reflex_sensor("model"), ReflexSensor::kModel);
  EXPECT_EQ(parse_reflex_sensor("fiber"), ReflexSensor::kFiber);
  for (ReflexSensor sensor : {ReflexSensor::kModel, ReflexSensor::kFiber}) {
    EXPECT_EQ(parse_reflex_sensor(to_string(sensor)), sensor);
  }
  for (const char* bad : {"fibre", "", "Model"}) {
    try {
      parse_reflex_sensor(bad);
      ADD_FAILURE() << "no throw for " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                std::string("reflex.sensor must be \"model\" or \"fiber\", got \"") + bad + "\"");
    }
  }
}

TEST(ReflexSensor, TableIiThresholdsAndGains) {
  const ReflexConfig model = table_ii_reflex_config(ReflexSensor::kModel);
  EXPECT_EQ(model.sensor, ReflexSensor::kModel);
  EXPECT_DOUBLE_EQ(model.v_thr_m_s, 70.0e-3);                // 70 mm/s
  EXPECT_DOUBLE_EQ(model.k_pa_s_per_m, 1e6 / 800.0 / 1e-3);  // 1/800 MPa per mm/s
  const ReflexConfig fiber = table_ii_reflex_config(ReflexSensor::kFiber);
  EXPECT_EQ(fiber.sensor, ReflexSensor::kFiber);
  EXPECT_DOUBLE_EQ(fiber.v_thr_m_s, 25.0e-3);
  EXPECT_DOUBLE_EQ(fiber.k_pa_s_per_m, 1e6 / 300.0 / 1e-3);
  // the other fields keep their defaults
  EXPECT_DOUBLE_EQ(fiber.duration_s, ReflexConfig{}.duration_s);
  EXPECT_EQ(fiber.enabled, ReflexConfig{}.enabled);
}

}  // namespace
}  // namespace pamsim
