// sensor_hardware_suite_test.cc: the pressure sensor, fiber sensor and encoder as hardware
// inside the SensorSuite (sensing.h): with their models off every reading is bit-identical
// to pamsim before they existed (a digest pinned from that build) and to a configuration
// whose hardware keys are all moved; with the pressure model on, the gauge's and the fiber's
// readings (the existing noise stream) are unchanged, each muscle has its own instrument,
// and a trial is fixed by its seeds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "base/double_bits.h"
#include "sensing/sensing.h"
#include "sensing_test_util.h"

namespace pamsim {
namespace {

using test::fields;

// 300 ticks of both Table IV muscles under moving pressures, forces and lengths
std::vector<std::vector<MuscleReading>> run(const SensingConfig& config, std::uint64_t seed) {
  SensorSuite suite(config, {test::table_iv_agonist(), test::table_iv_antagonist()}, seed);
  std::vector<MuscleTruth> truth(2);
  std::vector<std::vector<MuscleReading>> out;
  for (int i = 0; i < 300; ++i) {
    const double t = 0.01 * i;
    for (int j = 0; j < 2; ++j) {
      truth[j].pressure_pa = 0.4e6 + 0.2e6 * std::sin(2.0 + t * (1 + j));
      truth[j].force_n = 30.0 + 20.0 * std::sin(t * (2 + j));
      truth[j].length_m = 0.16 + 0.01 * std::sin(3.0 * t + j);
    }
    std::vector<MuscleReading> readings(2);
    suite.sample(truth, &readings);
    out.push_back(readings);
  }
  return out;
}

// FNV-1a over the bits of every field of every reading
std::uint64_t digest(const std::vector<std::vector<MuscleReading>>& readings) {
  std::uint64_t h = 1469598103934665603ull;
  for (const auto& tick : readings) {
    for (const MuscleReading& r : tick) {
      for (double x : fields(r)) {
        const std::uint64_t bits = double_bits(x);
        for (int k = 0; k < 8; ++k) {
          h ^= (bits >> (8 * k)) & 0xffu;
          h *= 1099511628211ull;
        }
      }
    }
  }
  return h;
}

TEST(SensorHardwareSuite, ModelsOffReadAsBeforeThem) {
  // pinned from the commit before the pressure, fiber and encoder models (dbf4891), with
  // every sensor at its default
  EXPECT_EQ(digest(run(SensingConfig{}, 1)), 0x9222a6387d6ab57dull);
  EXPECT_EQ(digest(run(SensingConfig{}, 7)), 0x546ae0db0cdac64bull);
}

TEST(SensorHardwareSuite, ModelsOffIgnoreTheirOtherKeys) {
  SensingConfig moved;
  PressureHardwareConfig& p = moved.sensors.pressure_hardware;
  p.bias_mean_pa = 5e3;
  p.bias_stddev_pa = 1e4;
  p.gain_error_stddev_pct = 3.0;
  p.dynamic_bias_stddev_pa = 2e3;
  p.hysteresis_pa = 1e4;
  p.response_time_s = 0.05;
  p.precision_pa = 1e3;
  moved.sensors.fiber_hardware.nonlinearity_pct = 30.0;
  moved.sensors.fiber_hardware.creep = {{0.5, 1.0}};
  moved.sensors.encoder.resolution_m = 1e-3;
  moved.sensors.gauge_hardware.instrument_seed = 99;
  EXPECT_EQ(digest(run(moved, 1)), digest(run(SensingConfig{}, 1)));
}

TEST(SensorHardwareSuite, PressureHardwareLeavesTheOtherSensorsStreamAlone) {
  SensingConfig on;
  on.sensors.pressure_hardware.enabled = true;
  const auto a = run(on, 3), b = run(SensingConfig{}, 3);
  int pressure_differs = 0;
  for (std::size_t tick = 0; tick < a.size(); ++tick) {
    for (int j = 0; j < 2; ++j) {
      EXPECT_EQ(a[tick][j].gauge_v, b[tick][j].gauge_v);
      EXPECT_EQ(a[tick][j].fiber_rate_m_s, b[tick][j].fiber_rate_m_s);
      EXPECT_EQ(a[tick][j].fiber_length_m, b[tick][j].fiber_length_m);
      pressure_differs += a[tick][j].pressure_meas_pa != b[tick][j].pressure_meas_pa;
    }
  }
  EXPECT_GT(pressure_differs, 550);
}

TEST(SensorHardwareSuite, EachMuscleHasItsOwnInstrumentFixedByTheSeeds) {
  SensingConfig on;
  on.sensors.pressure_hardware.enabled = true;
  on.sensors.pressure_noise_pa = 0.0;
  on.sensors.pressure_adc_bits = 0;
  on.sensors.pressure_hardware.dynamic_bias_stddev_pa = 0.0;
  // both muscles at one pressure read differently: two instruments
  SensorSuite suite(on, {test::table_iv_agonist(), test::table_iv_antagonist()}, 1);
  std::vector<MuscleTruth> truth(2);
  for (MuscleTruth& t : truth) t = {0.4e6, 30.0, 0.16};
  std::vector<MuscleReading> r(2);
  suite.sample(truth, &r);
  EXPECT_NE(r[0].pressure_meas_pa, r[1].pressure_meas_pa);
  // the same seeds read the same; another instrument seed builds other sensors
  EXPECT_EQ(digest(run(on, 5)), digest(run(on, 5)));
  SensingConfig other = on;
  other.sensors.gauge_hardware.instrument_seed = 2;
  EXPECT_NE(digest(run(other, 5)), digest(run(on, 5)));
  // with the drift on, another trial seed moves it
  SensingConfig drifting = on;
  drifting.sensors.pressure_hardware.dynamic_bias_stddev_pa = 400.0;
  const auto a = run(drifting, 5), b = run(drifting, 6);
  EXPECT_NE(a[0][0].pressure_meas_pa, b[0][0].pressure_meas_pa);
}

}  // namespace
}  // namespace pamsim
