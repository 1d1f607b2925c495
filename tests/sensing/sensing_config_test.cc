// sensing_config_test.cc: a bad-value test for every key validate(SensingConfig) and
// validate(MuscleSensorSpec) check: the message names the key, quotes the value and says what
// is allowed; a spring law's coefficient keys follow the law; an unset muscle is refused.
#include "sensing/sensing.h"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sensing_test_util.h"

#include "base/input_error.h"
#include "base/no_value.h"
#include "base/units.h"
#include "pam_actuator/spring_model.h"

namespace pamsim {
namespace {

using test::expect_bad_value;
using test::noise_free;
using test::table_iv_agonist;
using test::table_iv_antagonist;
using test::table_iv_muscles;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// --- bad values: every validated key; the message names the key and quotes the value ---

using BadSensing = test::BadValueOf<SensingConfig>;

std::vector<BadSensing> bad_sensing_values() {
  using C = SensingConfig&;
  return {
      {"sim.control_hz", "0", [](C c) { c.control_hz = 0.0; }},
      {"sim.control_hz", "-100", [](C c) { c.control_hz = -100.0; }},
      {"sim.control_hz", "nan", [](C c) { c.control_hz = kNaN; }},
      {"sensors.pressure_noise_MPa", "-0.001", [](C c) { c.sensors.pressure_noise_pa = -1000.0; }},
      {"sensors.pressure_noise_MPa", "nan", [](C c) { c.sensors.pressure_noise_pa = kNaN; }},
      {"sensors.pressure_bias_MPa", "1.5", [](C c) { c.sensors.pressure_bias_pa = 1.5e6; }},
      {"sensors.pressure_bias_MPa", "-1", [](C c) { c.sensors.pressure_bias_pa = -1e6; }},
      {"sensors.pressure_bias_MPa", "nan", [](C c) { c.sensors.pressure_bias_pa = kNaN; }},
      {"sensors.pressure_adc_bits", "-1", [](C c) { c.sensors.pressure_adc_bits = -1; }},
      {"sensors.pressure_adc_bits", "2", [](C c) { c.sensors.pressure_adc_bits = 2; }},
      {"sensors.pressure_adc_bits", "32", [](C c) { c.sensors.pressure_adc_bits = 32; }},
      {"sensors.pressure_adc_min_V", "nan", [](C c) { c.sensors.pressure_adc_min_v = kNaN; }},
      {"sensors.pressure_adc_max_V", "-1", [](C c) { c.sensors.pressure_adc_max_v = -1.0; }},
      {"sensors.pressure_adc_max_V", "0", [](C c) { c.sensors.pressure_adc_max_v = 0.0; }},
      {"sensors.pressure_adc_max_V", "nan", [](C c) { c.sensors.pressure_adc_max_v = kNaN; }},
      {"sensors.pressure_lowpass_hz", "-5", [](C c) { c.sensors.pressure_lowpass_hz = -5.0; }},
      {"sensors.pressure_lowpass_hz", "51", [](C c) { c.sensors.pressure_lowpass_hz = 51.0; }},
      {"sensors.pressure_lowpass_hz", "nan", [](C c) { c.sensors.pressure_lowpass_hz = kNaN; }},
      {"sensors.gauge_noise_V", "-0.001", [](C c) { c.sensors.gauge_noise_v = -1e-3; }},
      {"sensors.gauge_noise_V", "nan", [](C c) { c.sensors.gauge_noise_v = kNaN; }},
      {"sensors.gauge_adc_bits", "3", [](C c) { c.sensors.gauge_adc_bits = 3; }},
      {"sensors.gauge_adc_bits", "25", [](C c) { c.sensors.gauge_adc_bits = 25; }},
      {"sensors.gauge_adc_min_V", "-inf", [](C c) { c.sensors.gauge_adc_min_v = -kInfinity; }},
      {"sensors.gauge_adc_max_V", "-5", [](C c) { c.sensors.gauge_adc_max_v = -5.0; }},
      {"sensors.gauge_adc_max_V", "nan", [](C c) { c.sensors.gauge_adc_max_v = kNaN; }},
      {"sensors.fiber_noise_mm_s", "-2", [](C c) { c.sensors.fiber_noise_m_s = -2e-3; }},
      {"sensors.fiber_noise_mm_s", "nan", [](C c) { c.sensors.fiber_noise_m_s = kNaN; }},
      {"sensors.noise_scale", "-1", [](C c) { c.sensors.noise_scale = -1.0; }},
      {"sensors.noise_scale", "1001", [](C c) { c.sensors.noise_scale = 1001.0; }},
      {"sensors.noise_scale", "nan", [](C c) { c.sensors.noise_scale = kNaN; }},
      // the sensors as hardware: one per file, the rest in their own tests
      {"sensors.encoder.resolution_mm", "0", [](C c) { c.sensors.encoder.resolution_m = 0.0; }},
      {"sensors.encoder.resolution_mm", "nan", [](C c) { c.sensors.encoder.resolution_m = kNaN; }},
      {"sensors.pressure.dynamic_bias_correlation_time_s", "0",
       [](C c) { c.sensors.pressure_hardware.dynamic_bias_correlation_time_s = 0.0; }},
      {"sensors.fiber.span_mm", "-1", [](C c) { c.sensors.fiber_hardware.span_m = -1e-3; }},
      {"reflex.lowpass_hz", "-1", [](C c) { c.velocity_lowpass_hz = -1.0; }},
      {"reflex.lowpass_hz", "60", [](C c) { c.velocity_lowpass_hz = 60.0; }},
      {"reflex.lowpass_hz", "nan", [](C c) { c.velocity_lowpass_hz = kNaN; }},
      // the cutoffs are checked against the configured control rate, not 100 Hz
      {"reflex.lowpass_hz", "30",
       [](C c) {
         c.control_hz = 50.0;
         c.velocity_lowpass_hz = 30.0;
       }},
      {"sensors.pressure_lowpass_hz", "30",
       [](C c) {
         c.control_hz = 50.0;
         c.sensors.pressure_lowpass_hz = 30.0;
       }},
  };
}

struct BadMuscle {
  std::string key;    // after the muscle's own key
  std::string value;  // as the message quotes it (paper units for the spring)
  std::function<void(MuscleSensorSpec&)> set;
};

MuscleSensorSpec eq4_muscle() {
  return {"muscles.eq4",
          spring_model_from_paper_units(SpringLaw::kEq4, -60.0, 170.0,
                                        {1.0, 0.2, 5.0, -0.1, 0.01, 0.3}),
          StrainGaugeParams{2.0e-3, 0.0}};
}
MuscleSensorSpec eq5_muscle() {
  return {
      "muscles.eq5",
      spring_model_from_paper_units(SpringLaw::kEq5, -60.0, 170.0, {1.0, 0.2, 5.0, -0.1, 0.01, 0}),
      StrainGaugeParams{2.0e-3, 0.0}};
}

std::vector<BadMuscle> bad_muscle_values() {
  using M = MuscleSensorSpec&;
  std::vector<BadMuscle> bad = {
      {".strain_gauge.q_V_per_N", "0", [](M m) { m.gauge.q_v_per_n = 0.0; }},
      {".strain_gauge.q_V_per_N", "-0.00433", [](M m) { m.gauge.q_v_per_n = -4.33e-3; }},
      {".strain_gauge.q_V_per_N", "nan", [](M m) { m.gauge.q_v_per_n = kNaN; }},
      {".strain_gauge.V_base_V", "nan", [](M m) { m.gauge.v_base_v = kNaN; }},
      {".strain_gauge.V_base_V", "inf", [](M m) { m.gauge.v_base_v = kInfinity; }},
      {".spring.m", "nan", [](M m) { m.estimator.m_m_per_pa = kNaN; }},
      {".spring.m", "-inf", [](M m) { m.estimator.m_m_per_pa = -kInfinity; }},
      {".spring.h", "-100", [](M m) { m.estimator.h_m = -0.1; }},  // [mm] as in the file
      {".spring.h", "0", [](M m) { m.estimator.h_m = 0.0; }},
      {".spring.h", "nan", [](M m) { m.estimator.h_m = kNaN; }},
  };
  // every coefficient of the law, named as in the paper (Eq. (3): a0..a3)
  for (int k = 0; k < 4; ++k) {
    bad.push_back(
        {".spring.a" + std::to_string(k), "nan", [k](M m) { m.estimator.coef[k] = kNaN; }});
  }
  return bad;
}

TEST(SensingConfig, DefaultsAreValid) {
  EXPECT_NO_THROW(validate(SensingConfig{}));
  EXPECT_NO_THROW(validate(noise_free()));
  for (const MuscleSensorSpec& m :
       {table_iv_agonist(), table_iv_antagonist(), eq4_muscle(), eq5_muscle()}) {
    EXPECT_NO_THROW(validate(m)) << m.key;
  }
}

TEST(SensingConfig, EveryBadValueThrowsNamingTheKeyAndValue) {
  for (const BadSensing& bad : bad_sensing_values()) {
    SCOPED_TRACE(bad.key + " = " + bad.value);
    SensingConfig config;
    bad.set(config);
    expect_bad_value([&] { validate(config); }, bad.key, bad.value);
    // the constructor validates too
    expect_bad_value([&] { SensorSuite{config, table_iv_muscles(), 1}; }, bad.key, bad.value);
  }
}

TEST(SensingConfig, MessageQuotesTheValueAndWhatIsAllowed) {
  SensingConfig config;
  config.control_hz = 50.0;
  config.velocity_lowpass_hz = 30.0;
  try {
    validate(config);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "reflex.lowpass_hz must be 0 (off) or in (0, 25] Hz (sim.control_hz / 2), "
                 "got 30");
  }
}

TEST(MuscleSensorSpec, EveryBadValueThrowsNamingTheMusclesKeyAndValue) {
  for (const BadMuscle& bad : bad_muscle_values()) {
    SCOPED_TRACE(bad.key + " = " + bad.value);
    MuscleSensorSpec muscle = table_iv_antagonist();
    bad.set(muscle);
    expect_bad_value([&] { validate(muscle); }, "muscles.antagonist" + bad.key, bad.value);
    // the constructor checks every muscle, not only the first
    expect_bad_value(
        [&] {
          SensorSuite{SensingConfig{}, {table_iv_agonist(), muscle}, 1};
        },
        "muscles.antagonist" + bad.key, bad.value);
  }
}

TEST(MuscleSensorSpec, CoefficientKeysFollowTheLaw) {
  // Eq. (4) names b0..b5, Eq. (5) c0..c4
  MuscleSensorSpec eq4 = eq4_muscle();
  eq4.estimator.coef[5] = kNaN;
  expect_bad_value([&] { validate(eq4); }, "muscles.eq4.spring.b5", "nan");
  MuscleSensorSpec eq5 = eq5_muscle();
  eq5.estimator.coef[4] = kInfinity;
  expect_bad_value([&] { validate(eq5); }, "muscles.eq5.spring.c4", "inf");
}

TEST(MuscleSensorSpec, UnsetMuscleIsRejected) {
  // a muscle whose parameter file had no [strain_gauge] table (q = 0) and no spring
  MuscleSensorSpec unset;
  unset.key = "muscles.elbow";
  expect_bad_value([&] { validate(unset); }, "muscles.elbow.strain_gauge.q_V_per_N", "0");
  unset.gauge.q_v_per_n = 2.25e-3;
  expect_bad_value([&] { validate(unset); }, "muscles.elbow.spring.h", "0");
}

}  // namespace
}  // namespace pamsim
