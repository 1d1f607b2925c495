// sensing_test_util.h: what the sensing and controller tests share: the Table IV arm's
// muscles as the sensing sees them, the bad values' cases and the check that a bad value's
// message names its key and quotes the value, and a reading's fields as one list.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/input_error.h"
#include "pam_actuator/spring_model.h"
#include "sensing/sensing.h"

namespace pamsim::test {

// the Table IV arm (Yoshida and Hosoda): spring laws and strain gauges of both muscles
inline MuscleSensorSpec table_iv_agonist(const std::string& key = "muscles.agonist") {
  return {key,
          spring_model_from_paper_units(SpringLaw::kEq3, -60.1, 170.1,
                                        {0.911, 0.256, 7.00, -0.201, 0, 0}),
          StrainGaugeParams{2.25e-3, 0.0}};
}
inline MuscleSensorSpec table_iv_antagonist(const std::string& key = "muscles.antagonist") {
  return {key,
          spring_model_from_paper_units(SpringLaw::kEq3, -70.3, 178.5,
                                        {22.4, -0.129, 1.24, 0.871, 0, 0}),
          StrainGaugeParams{4.33e-3, 0.0}};
}

// A bad value of one key of a Config: the key, the value as the message quotes it, and how
// to put it into a valid Config.
template <typename Config>
struct BadValueOf {
  std::string key;
  std::string value;
  std::function<void(Config&)> set;
};

// `call` throws InputError "<key> must be ..., got <value>"
inline void expect_bad_value(const std::function<void()>& call, const std::string& key,
                             const std::string& value) {
  try {
    call();
    ADD_FAILURE() << "no throw for " << key << " = " << value;
  } catch (const InputError& e) {
    const std::string what = e.what();
    const std::string tail = ", got " + value;
    EXPECT_EQ(what.rfind(key + " must be ", 0), 0u) << key << ": " << what;
    EXPECT_TRUE(what.size() >= tail.size() &&
                what.compare(what.size() - tail.size(), tail.size(), tail) == 0)
        << "expected to end with \"" << tail << "\": " << what;
  }
}

// every field of a reading, in declaration order
inline std::vector<double> fields(const MuscleReading& r) {
  return {r.pressure_sensor_v,  r.gauge_v,          r.fiber_rate_m_s, r.fiber_length_m,
          r.fiber_velocity_m_s, r.pressure_meas_pa, r.force_meas_n,   r.length_est_m,
          r.velocity_est_m_s};
}

// Both of Table IV's muscles, agonist first.
inline std::vector<MuscleSensorSpec> table_iv_muscles() {
  return {table_iv_agonist(), table_iv_antagonist()};
}

// No noise, ideal converters, no filters: the readings should equal the truth.
inline SensingConfig noise_free() {
  SensingConfig config;
  config.sensors.pressure_noise_pa = 0.0;
  config.sensors.pressure_adc_bits = 0;
  config.sensors.gauge_noise_v = 0.0;
  config.sensors.gauge_adc_bits = 0;
  config.sensors.fiber_noise_m_s = 0.0;
  return config;
}

}  // namespace pamsim::test
