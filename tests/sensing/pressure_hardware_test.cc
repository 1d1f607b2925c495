// pressure_hardware_test.cc: the PSE540 as hardware (pressure_hardware.h) against closed
// forms, one error source at a time: the static error p (1 + g) + b of one drawn instrument,
// the hysteresis loop's width, the first-order step response at the response time, the
// dynamic bias's stationary spread; the instrument seed fixes the draws and another seed
// changes them; the PressureSensor around it; and every bad key is named.
#include "sensing/pressure_hardware.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "sensing/sensors.h"
#include "sensing_test_util.h"
#include "base/control_step.h"
#include "base/no_value.h"

namespace pamsim {
namespace {

using pamsim_test::kControlDt;

// one source at a time: everything else off
PressureHardwareConfig only(void (*set)(PressureHardwareConfig&)) {
  PressureHardwareConfig c;
  c.enabled = true;
  c.bias_stddev_pa = 0.0;
  c.gain_error_stddev_pct = 0.0;
  c.dynamic_bias_stddev_pa = 0.0;
  c.hysteresis_pa = 0.0;
  c.response_time_s = 0.0;
  set(c);
  return c;
}

PressureHardware build(const PressureHardwareConfig& c, std::uint64_t instrument_seed = 1,
                       std::uint64_t trial_seed = 1, double dt = kControlDt) {
  std::mt19937_64 instrument(instrument_seed);
  return PressureHardware(c, instrument, std::mt19937_64(trial_seed), dt);
}

TEST(PressureHardwareTest, OffsetAndGainOfTheDrawnInstrument) {
  const PressureHardwareConfig c = only([](PressureHardwareConfig& c) {
    c.bias_mean_pa = 1000.0;
    c.bias_stddev_pa = 4700.0;
    c.gain_error_stddev_pct = 0.47;
  });
  PressureHardware sensor = build(c, 9);
  // the draws, by hand: two normals of the instrument's generator
  std::mt19937_64 by_hand(9);
  const double b = 1000.0 + 4700.0 * standard_normal(by_hand);
  const double g = 0.0047 * standard_normal(by_hand);
  EXPECT_DOUBLE_EQ(sensor.bias_pa(), b);
  EXPECT_DOUBLE_EQ(sensor.gain_error(), g);
  for (double p : {0.0, 0.2e6, 0.6e6, 1.0e6}) {
    EXPECT_NEAR(sensor.sensed_pa(p), p * (1.0 + g) + b, 1e-9) << p;
  }
}

TEST(PressureHardwareTest, TheInstrumentSeedFixesTheDrawsAndAnotherChangesThem) {
  const PressureHardwareConfig c;  // the PSE540 class defaults
  const PressureHardware a = build(c, 5, 1), same = build(c, 5, 2), other = build(c, 6, 1);
  EXPECT_EQ(a.bias_pa(), same.bias_pa());  // the trial's seed does not rebuild it
  EXPECT_EQ(a.gain_error(), same.gain_error());
  EXPECT_NE(a.bias_pa(), other.bias_pa());
  EXPECT_NE(a.gain_error(), other.gain_error());
}

TEST(PressureHardwareTest, HysteresisLoopHasItsWidth) {
  const double h = 2000.0;
  PressureHardware sensor =
      build(only([](PressureHardwareConfig& c) { c.hysteresis_pa = 2000.0; }));
  // up from 0.1 to 0.6 MPa and back down: at 0.35 MPa the rising reading trails by h/2, the
  // falling one leads by h/2, so the loop is h wide
  double rising = 0.0, falling = 0.0;
  for (int k = 0; k <= 50; ++k) {
    const double r = sensor.sensed_pa(0.1e6 + 0.01e6 * k);
    if (k == 25) rising = r;
  }
  for (int k = 50; k >= 0; --k) {
    const double r = sensor.sensed_pa(0.1e6 + 0.01e6 * k);
    if (k == 25) falling = r;
  }
  EXPECT_NEAR(rising, 0.35e6 - h / 2, 1e-6);
  EXPECT_NEAR(falling, 0.35e6 + h / 2, 1e-6);
  EXPECT_NEAR(falling - rising, h, 1e-6);
  // a reversal smaller than the band does not move the reading
  const double held = sensor.sensed_pa(0.1e6 + 0.5 * h);
  EXPECT_NEAR(held, 0.1e6 + h / 2, 1e-6);
}

TEST(PressureHardwareTest, FirstOrderStepResponseReachesNinetyPercentAtTheResponseTime) {
  // a 50 ms response sampled at 1 kHz: tau = t_r / ln 10, y_n = 1 - exp(-n dt / tau)
  const double t_r = 0.050, dt = 1e-3;
  const PressureHardwareConfig c =
      only([](PressureHardwareConfig& c) { c.response_time_s = 0.050; });
  PressureHardware sensor = build(c, 1, 1, dt);
  sensor.sensed_pa(0.0);
  const double tau = t_r / std::log(10.0);
  for (int n = 1; n <= 100; ++n) {
    const double y = sensor.sensed_pa(0.5e6) / 0.5e6;
    EXPECT_NEAR(y, 1.0 - std::exp(-n * dt / tau), 1e-12) << n;
    if (n == 50) {
      EXPECT_NEAR(y, 0.9, 1e-12);
    }
  }
  EXPECT_DOUBLE_EQ(response_cutoff_hz(0.0), 0.0);
}

TEST(PressureHardwareTest, DynamicBiasHasItsStationarySpreadAcrossTrials) {
  const PressureHardwareConfig c = only([](PressureHardwareConfig& c) {
    c.dynamic_bias_stddev_pa = 400.0;
    c.dynamic_bias_correlation_time_s = 3600.0;
  });
  const int n = 20000;
  double sum2 = 0.0;
  for (int trial = 0; trial < n; ++trial) {
    PressureHardware sensor = build(c, 1, 1000 + trial);
    const double e = sensor.sensed_pa(0.4e6) - 0.4e6;
    sum2 += e * e;
  }
  EXPECT_NEAR(std::sqrt(sum2 / n), 400.0, 400.0 * 0.03);
}

TEST(PressureHardwareTest, TheSensorRoundsToItsPrecisionAfterTheNoise) {
  SensorConfig config;
  config.pressure_adc_bits = 0;
  config.pressure_noise_pa = 0.0;
  const PressureHardwareConfig c = only([](PressureHardwareConfig& c) { c.precision_pa = 5000.0; });
  PressureSensor sensor(config, build(c));
  std::mt19937_64 rng(1);
  EXPECT_NEAR(sensor.sample(0.4121e6, rng).pressure_pa, 0.41e6, 1e-6);
  EXPECT_NEAR(sensor.sample(0.4126e6, rng).pressure_pa, 0.415e6, 1e-6);
}

TEST(PressureHardwareTest, EveryBadKeyIsNamed) {
  using C = PressureHardwareConfig;
  const test::BadValueOf<C> cases[] = {
      {"sensors.pressure.bias_mean_MPa", "nan", [](C& c) { c.bias_mean_pa = kNaN; }},
      {"sensors.pressure.bias_stddev_MPa", "-0.001", [](C& c) { c.bias_stddev_pa = -1000; }},
      {"sensors.pressure.gain_error_stddev_pct", "-1", [](C& c) { c.gain_error_stddev_pct = -1; }},
      {"sensors.pressure.gain_error_stddev_pct", "nan",
       [](C& c) { c.gain_error_stddev_pct = kNaN; }},
      {"sensors.pressure.dynamic_bias_stddev_MPa", "-0.001",
       [](C& c) { c.dynamic_bias_stddev_pa = -1000; }},
      {"sensors.pressure.dynamic_bias_correlation_time_s", "0",
       [](C& c) { c.dynamic_bias_correlation_time_s = 0; }},
      {"sensors.pressure.dynamic_bias_correlation_time_s", "nan",
       [](C& c) { c.dynamic_bias_correlation_time_s = kNaN; }},
      {"sensors.pressure.hysteresis_MPa", "-0.002", [](C& c) { c.hysteresis_pa = -2000; }},
      {"sensors.pressure.response_time_ms", "-1", [](C& c) { c.response_time_s = -1e-3; }},
      {"sensors.pressure.precision_MPa", "-0.001", [](C& c) { c.precision_pa = -1000; }},
  };
  for (const auto& k : cases) {
    C c;
    k.set(c);
    test::expect_bad_value([&] { validate(c); }, k.key, k.value);
  }
  EXPECT_NO_THROW(validate(PressureHardwareConfig{}));
}

}  // namespace
}  // namespace pamsim
