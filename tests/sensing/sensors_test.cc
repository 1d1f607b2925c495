// sensors_test.cc: PSE540 transfer, ADC quantisation and saturation, the strain gauge's
// Eq. (8) and slack reading, the fiber sensor's calibration and integration, noise level
// and determinism per seed.
#include "sensing/sensors.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace pamsim {
namespace {

SensorConfig noise_free_sensors() {
  SensorConfig c;
  c.pressure_noise_pa = 0.0;
  c.gauge_noise_v = 0.0;
  c.fiber_noise_m_s = 0.0;
  return c;
}

TEST(Pse540, TransferIsOneToFiveVoltOverZeroToOneMPa) {
  EXPECT_DOUBLE_EQ(pse540_voltage(0.0), 1.0);
  EXPECT_DOUBLE_EQ(pse540_voltage(1.0e6), 5.0);
  EXPECT_DOUBLE_EQ(pse540_voltage(0.4e6), 2.6);
  EXPECT_NEAR(pse540_pressure_pa(pse540_voltage(0.37e6)), 0.37e6, 1e-9);
  EXPECT_DOUBLE_EQ(pse540_pressure_pa(1.0), 0.0);
}

TEST(Adc, QuantisationStepAndRounding) {
  const AdcParams adc{12, 0.0, 5.0};
  const double step = adc_step_v(adc);
  EXPECT_DOUBLE_EQ(step, 5.0 / 4095.0);
  for (double v = 0.0; v <= 5.0; v += 0.0137) {
    const double q = adc_read(adc, v);
    EXPECT_LE(std::abs(q - v), 0.5 * step + 1e-12);
    const double code = q / step;
    EXPECT_NEAR(code, std::round(code), 1e-9);
  }
  // two inputs within one step of the same level read the same
  EXPECT_DOUBLE_EQ(adc_read(adc, 100 * step + 0.4 * step), adc_read(adc, 100 * step - 0.4 * step));
  EXPECT_NEAR(adc_read(adc, 100.6 * step) - adc_read(adc, 100.4 * step), step, 1e-12);
  // 10-bit: coarser
  EXPECT_DOUBLE_EQ(adc_step_v(AdcParams{10, 0.0, 5.0}), 5.0 / 1023.0);
  // ideal converter: no quantisation
  EXPECT_DOUBLE_EQ(adc_read(AdcParams{0, 0.0, 5.0}, 1.23456789), 1.23456789);
}

TEST(Adc, SaturatesAtItsRange) {
  const AdcParams adc{12, 0.0, 5.0};
  EXPECT_DOUBLE_EQ(adc_read(adc, -0.3), 0.0);
  EXPECT_DOUBLE_EQ(adc_read(adc, 5.0), 5.0);
  EXPECT_DOUBLE_EQ(adc_read(adc, 7.0), 5.0);
  EXPECT_DOUBLE_EQ(adc_read(AdcParams{0, -1.0, 1.0}, 3.0), 1.0);
}

TEST(PressureSensor, NoiseFreeReadingAndSaturation) {
  std::mt19937_64 rng(1);
  SensorConfig c = noise_free_sensors();
  PressureSensor sensor(c);
  const PressureReading r = sensor.sample(0.4e6, rng);
  EXPECT_NEAR(r.voltage_v, 2.6, 0.5 * adc_step_v(AdcParams{12, 0.0, 5.0}) + 1e-12);
  // one ADC step is 5/4095 V = 305 Pa
  EXPECT_NEAR(r.pressure_pa, 0.4e6, 153.0);
  // above 1 MPa the 0-5 V input saturates at 5 V, i.e. reads 1 MPa
  const PressureReading high = sensor.sample(1.3e6, rng);
  EXPECT_DOUBLE_EQ(high.voltage_v, 5.0);
  EXPECT_DOUBLE_EQ(high.pressure_pa, 1.0e6);
  // a bias shifts the reading
  c.pressure_adc_bits = 0;
  c.pressure_bias_pa = 0.02e6;
  EXPECT_NEAR(PressureSensor(c).sample(0.4e6, rng).pressure_pa, 0.42e6, 1e-6);
}

TEST(PressureSensor, NoiseStdMatchesConfigured) {
  SensorConfig c;
  c.pressure_noise_pa = 0.002e6;
  c.pressure_adc_bits = 0;
  PressureSensor sensor(c);
  std::mt19937_64 rng(42);
  const int n = 40000;
  double sum = 0.0;
  double sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double e = sensor.sample(0.4e6, rng).pressure_pa - 0.4e6;
    sum += e;
    sum2 += e * e;
  }
  const double mean = sum / n;
  const double std = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(std, 2000.0, 2000.0 * 0.03);
  EXPECT_NEAR(mean, 0.0, 4.0 * 2000.0 / std::sqrt(n));
}

TEST(StrainGauge, Eq8AndSlackReadsVBase) {
  std::mt19937_64 rng(3);
  SensorConfig c = noise_free_sensors();
  c.gauge_adc_bits = 0;
  StrainGauge gauge(StrainGaugeParams{2.25e-3, 0.3}, c);
  EXPECT_NEAR(gauge.sample(32.5, rng), 2.25e-3 * 32.5 + 0.3, 1e-15);
  // slack line: zero tension; the gauge cannot see compression either
  EXPECT_DOUBLE_EQ(gauge.sample(0.0, rng), 0.3);
  EXPECT_DOUBLE_EQ(gauge.sample(-5.0, rng), 0.3);
  // with the default 16-bit ADC, V_base to within half a step
  StrainGauge quantised(StrainGaugeParams{2.25e-3, 0.3}, noise_free_sensors());
  EXPECT_NEAR(quantised.sample(0.0, rng), 0.3, 0.5 * adc_step_v(AdcParams{16, -5.0, 5.0}));
}

TEST(StrainGauge, SlackReadingIsVBasePlusNoise) {
  SensorConfig c;
  c.gauge_noise_v = 1e-3;
  c.gauge_adc_bits = 0;
  StrainGauge gauge(StrainGaugeParams{4.33e-3, 0.1}, c);
  std::mt19937_64 rng(5);
  const int n = 40000;
  double sum = 0.0;
  double sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double e = gauge.sample(0.0, rng) - 0.1;
    sum += e;
    sum2 += e * e;
  }
  EXPECT_NEAR(sum / n, 0.0, 4.0 * 1e-3 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum2 / n), 1e-3, 1e-3 * 0.03);
}

TEST(FiberSensor, CalibratedToEncoderAndIntegratesRate) {
  std::mt19937_64 rng(7);
  FiberSensor fiber(noise_free_sensors(), 0.01);
  EXPECT_DOUBLE_EQ(fiber.sample(0.160, rng), 0.0);
  EXPECT_DOUBLE_EQ(fiber.length_m(), 0.160);
  // stretching at 150 mm/s
  for (int j = 1; j <= 20; ++j) {
    const double l = 0.160 + 0.150 * 0.01 * j;
    EXPECT_NEAR(fiber.sample(l, rng), 0.150, 1e-9);
    EXPECT_NEAR(fiber.length_m(), l, 1e-12);
  }
}

TEST(FiberSensor, NoiseStdMatchesConfigured) {
  SensorConfig c;
  c.fiber_noise_m_s = 3.0e-3;
  FiberSensor fiber(c, 0.01);
  std::mt19937_64 rng(11);
  const int n = 40000;
  double sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = fiber.sample(0.17, rng);
    sum2 += r * r;
  }
  EXPECT_NEAR(std::sqrt(sum2 / n), 3e-3, 3e-3 * 0.03);
}

// sensors.noise_scale multiplies each sensor's noise: the same normal draws, scaled, so a
// reading's error at scale 2.5 is exactly 2.5 times its error at scale 1 (same seed).
TEST(Sensors, NoiseScaleMultipliesEveryNoiseStd) {
  SensorConfig one;
  one.pressure_adc_bits = 0;
  one.gauge_adc_bits = 0;
  one.pressure_bias_pa = 0.01e6;  // not scaled
  SensorConfig scaled = one;
  scaled.noise_scale = 2.5;
  const StrainGaugeParams gauge{2.25e-3, 0.0};
  std::mt19937_64 a(5), b(5);
  for (int i = 0; i < 100; ++i) {
    const double p_err1 = PressureSensor(one).sample(0.4e6, a).pressure_pa - 0.41e6;
    const double p_err2 = PressureSensor(scaled).sample(0.4e6, b).pressure_pa - 0.41e6;
    EXPECT_NEAR(p_err2, 2.5 * p_err1, 1e-6 * std::abs(p_err1) + 1e-3);
    const double g_err1 = StrainGauge(gauge, one).sample(30.0, a) - gauge.q_v_per_n * 30.0;
    const double g_err2 = StrainGauge(gauge, scaled).sample(30.0, b) - gauge.q_v_per_n * 30.0;
    EXPECT_NEAR(g_err2, 2.5 * g_err1, 1e-9);
  }
  FiberSensor f1(one, 0.01), f2(scaled, 0.01);
  for (int i = 0; i < 100; ++i) {
    const double r1 = f1.sample(0.17, a), r2 = f2.sample(0.17, b);
    EXPECT_NEAR(r2, 2.5 * r1, 1e-12);
  }
  SensorConfig quiet = one;
  quiet.noise_scale = 0.0;
  EXPECT_NEAR(PressureSensor(quiet).sample(0.4e6, a).pressure_pa, 0.41e6, 1e-6);
}

TEST(Sensors, DeterministicPerSeed) {
  const SensorConfig c;  // default noise
  auto run = [&](std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    PressureSensor p(c);
    StrainGauge g(StrainGaugeParams{2.25e-3, 0.0}, c);
    FiberSensor f(c, 0.01);
    std::vector<double> out;
    for (int i = 0; i < 100; ++i) {
      out.push_back(p.sample(0.4e6, rng).voltage_v);
      out.push_back(g.sample(30.0, rng));
      out.push_back(f.sample(0.16, rng));
    }
    return out;
  };
  EXPECT_EQ(run(123), run(123));
  EXPECT_NE(run(123), run(124));
}

}  // namespace
}  // namespace pamsim
