// sensing_test.cc: the SensorSuite end to end on synthetic truth of the Table IV arm (every
// reading filled, noise-free readings equal to the truth, a stretch read as velocity on that
// muscle alone, the velocity low-pass against its step response, the pressure low-pass
// against the noise it removes, determinism per seed, each sensor's noise drawn in order).
// sensing_config_test.cc has the bad-value tests.
#include "sensing/sensing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sensing_test_util.h"

#include "base/input_error.h"
#include "pam_actuator/spring_model.h"
#include "base/units.h"
#include "sensing/lowpass_filter.h"
#include "sensing/sensors.h"
#include "base/control_step.h"
#include "base/no_value.h"

namespace pamsim {
namespace {

using pamsim_test::kControlDt;

using test::expect_bad_value;
using test::fields;
using test::noise_free;
using test::table_iv_agonist;
using test::table_iv_antagonist;
using test::table_iv_muscles;

// The arm at the falling-mass operating point (at -36 deg on the Table IV laws, as a
// prototype calibrated it): both muscles at 0.4 MPa, agonist d = 6.66 mm, antagonist
// d = 1.0 mm. The truth follows the same spring laws the estimators invert.
struct Plant {
  std::vector<MuscleSensorSpec> muscles = table_iv_muscles();
  std::vector<double> d_m = {6.66e-3, 1.0e-3};
  std::vector<double> p_pa = {0.4e6, 0.4e6};

  std::vector<MuscleTruth> truth() const {
    std::vector<MuscleTruth> t(muscles.size());
    for (std::size_t j = 0; j < muscles.size(); ++j) {
      t[j].pressure_pa = p_pa[j];
      t[j].force_n = spring_force(muscles[j].estimator, p_pa[j], d_m[j]);
      t[j].length_m = natural_length(muscles[j].estimator, p_pa[j]) + d_m[j];
    }
    return t;
  }
};

// `ticks` samples of a static plant; tick_hook(j, plant) may move it before tick j
std::vector<std::vector<MuscleReading>> run(
    SensorSuite* suite, Plant* plant, int ticks,
    const std::function<void(int, Plant*)>& tick_hook = nullptr) {
  std::vector<std::vector<MuscleReading>> out;
  for (int j = 0; j < ticks; ++j) {
    if (tick_hook) tick_hook(j, plant);
    std::vector<MuscleReading> readings(suite->muscle_count());
    suite->sample(plant->truth(), &readings);
    out.push_back(readings);
  }
  return out;
}

double rms(const std::vector<double>& x) {
  double sum2 = 0.0;
  for (double v : x) sum2 += v * v;
  return std::sqrt(sum2 / static_cast<double>(x.size()));
}

TEST(SensorSuite, FillsEveryReadingField) {
  Plant plant;
  SensorSuite suite(SensingConfig{}, plant.muscles, 7);
  ASSERT_EQ(suite.muscle_count(), 2);
  const std::vector<MuscleTruth> truth = plant.truth();
  const auto readings = run(&suite, &plant, 2);
  for (int tick = 0; tick < 2; ++tick) {
    for (int j = 0; j < 2; ++j) {
      SCOPED_TRACE("tick " + std::to_string(tick) + " muscle " + std::to_string(j));
      const MuscleReading& r = readings[tick][j];
      // every field starts NaN (MuscleReading::kNone): finite means written
      for (double v : fields(r)) EXPECT_TRUE(std::isfinite(v)) << v;
      // near the truth at the default noise: PSE540 at 0.4 MPa reads 1 + 4 * 0.4 V
      EXPECT_NEAR(r.pressure_sensor_v, 2.6, 0.02);
      EXPECT_NEAR(r.pressure_meas_pa, 0.4e6, 5e3);
      EXPECT_NEAR(r.gauge_v, plant.muscles[j].gauge.q_v_per_n * truth[j].force_n, 3e-3);
      EXPECT_NEAR(r.force_meas_n, truth[j].force_n, 1.0);
      EXPECT_NEAR(r.length_est_m, truth[j].length_m, 0.5e-3);
      EXPECT_NEAR(r.fiber_length_m, truth[j].length_m, 0.1e-3);
    }
  }
}

TEST(SensorSuite, NoiseFreeReadingsEqualTheTruth) {
  Plant plant;
  plant.muscles[1].gauge.v_base_v = 0.1;  // Eq. (9) subtracts the offset
  SensorSuite suite(noise_free(), plant.muscles, 1);
  const std::vector<MuscleTruth> truth = plant.truth();
  for (const std::vector<MuscleReading>& tick : run(&suite, &plant, 5)) {
    for (int j = 0; j < 2; ++j) {
      const MuscleReading& r = tick[j];
      const StrainGaugeParams& g = plant.muscles[j].gauge;
      EXPECT_NEAR(r.pressure_sensor_v, pse540_voltage(truth[j].pressure_pa), 1e-12);
      EXPECT_NEAR(r.gauge_v, g.q_v_per_n * truth[j].force_n + g.v_base_v, 1e-12);  // Eq. (8)
      EXPECT_NEAR(r.pressure_meas_pa, truth[j].pressure_pa, 1e-6);
      EXPECT_NEAR(r.force_meas_n, truth[j].force_n, 1e-9);
      EXPECT_NEAR(r.length_est_m, truth[j].length_m, 1e-9);
      EXPECT_NEAR(r.fiber_length_m, truth[j].length_m, 1e-12);
      EXPECT_NEAR(r.velocity_est_m_s, 0.0, 1e-9);
      EXPECT_EQ(r.fiber_rate_m_s, 0.0);
      EXPECT_EQ(r.fiber_velocity_m_s, 0.0);
    }
  }
}

TEST(SensorSuite, StretchReadsAsVelocityOnThatMuscleOnly) {
  // noise-free; from tick 10 the agonist is stretched at 150 mm/s, the antagonist holds
  Plant plant;
  SensorSuite suite(noise_free(), plant.muscles, 1);
  const auto readings = run(&suite, &plant, 20, [](int j, Plant* p) {
    if (j >= 10) p->d_m[0] += 0.150 * kControlDt;
  });
  for (int tick = 0; tick < 20; ++tick) {
    const double v_true = tick >= 10 ? 0.150 : 0.0;
    const MuscleReading& ago = readings[tick][0];
    const MuscleReading& anta = readings[tick][1];
    // Eq. (11) at constant pressure: the length moves by d alone
    EXPECT_NEAR(ago.velocity_est_m_s, v_true, 1e-6) << tick;
    EXPECT_NEAR(ago.fiber_rate_m_s, v_true, 1e-9) << tick;
    EXPECT_NEAR(ago.fiber_velocity_m_s, v_true, 1e-9) << tick;  // reflex.lowpass_hz = 0
    const double d_m = 6.66e-3 + std::max(0, tick - 9) * 0.150 * kControlDt;
    EXPECT_NEAR(ago.length_est_m, natural_length(plant.muscles[0].estimator, 0.4e6) + d_m, 1e-9);
    EXPECT_NEAR(anta.velocity_est_m_s, 0.0, 1e-9) << tick;
    EXPECT_EQ(anta.fiber_rate_m_s, 0.0) << tick;
  }
}

TEST(SensorSuite, VelocityLowpassIsFirstOrderOnBothVelocities) {
  // reflex.lowpass_hz filters the estimate of Eq. (11) and the fiber rate alike; a step in
  // stretch velocity at tick 10 reads v (1 - (1 - alpha)^(n + 1)) n ticks later
  // (lowpass_filter.h), while the raw fiber rate steps at once
  SensingConfig config = noise_free();
  config.velocity_lowpass_hz = 10.0;
  Plant plant;
  SensorSuite suite(config, plant.muscles, 1);
  const auto readings = run(&suite, &plant, 30, [](int j, Plant* p) {
    if (j >= 10) p->d_m[0] += 0.150 * kControlDt;
  });
  const double alpha = 1.0 - std::exp(-2.0 * units::kPi * 10.0 * kControlDt);
  for (int tick = 0; tick < 30; ++tick) {
    const int n = tick - 10;
    const double v = n < 0 ? 0.0 : 0.150 * (1.0 - std::pow(1.0 - alpha, n + 1));
    const MuscleReading& ago = readings[tick][0];
    EXPECT_NEAR(ago.velocity_est_m_s, v, 1e-6) << tick;
    EXPECT_NEAR(ago.fiber_velocity_m_s, v, 1e-9) << tick;
    EXPECT_NEAR(ago.fiber_rate_m_s, n < 0 ? 0.0 : 0.150, 1e-9) << tick;
  }
  // the filter lags: 10 ticks in, still short of the true 150 mm/s
  EXPECT_LT(readings[10][0].velocity_est_m_s, 0.75 * 0.150);
}

TEST(SensorSuite, PressureLowpassRemovesNoiseThatReadsAsVelocity) {
  // Pressure noise alone (sigma 3 kPa, ideal gauge and converters) moves the estimated
  // length by dl/dp = m + dd/dp at constant force, so Eq. (11) reads white noise of
  //   sigma_v = sqrt(2) sigma_p |dl/dp| / dt
  // on a static arm. A first-order low-pass on the pressure (alpha per tick) scales the
  // tick-to-tick difference of white noise by alpha / sqrt(2 - alpha).
  const double sigma_p_pa = 3e3;
  const MuscleSensorSpec ago = table_iv_agonist();
  const double p_pa = 0.4e6;
  const double f_n = spring_force(ago.estimator, p_pa, 6.66e-3);
  // dl/dp from the spring law itself, by a central difference
  auto length_m = [&](double p) {
    return natural_length(ago.estimator, p) + invert_spring_model(ago.estimator, p, f_n).d_m;
  };
  const double dl_dp = (length_m(p_pa + 1e3) - length_m(p_pa - 1e3)) / 2e3;
  ASSERT_NEAR(dl_dp * 1e9, -66.3, 0.5);  // [mm/MPa]: -60.1 from l_n, -6.2 from d

  auto velocity_rms = [&](double pressure_lowpass_hz) {
    SensingConfig config = noise_free();
    config.sensors.pressure_noise_pa = sigma_p_pa;
    config.sensors.pressure_lowpass_hz = pressure_lowpass_hz;
    Plant plant;
    plant.muscles = {ago};
    plant.d_m = {6.66e-3};
    plant.p_pa = {p_pa};
    SensorSuite suite(config, plant.muscles, 3);
    std::vector<double> v;
    const auto readings = run(&suite, &plant, 4000);
    for (std::size_t tick = 1; tick < readings.size(); ++tick) {
      v.push_back(readings[tick][0].velocity_est_m_s);
    }
    return rms(v);
  };
  const double unfiltered = std::sqrt(2.0) * sigma_p_pa * std::abs(dl_dp) / kControlDt;
  const double alpha = lowpass_alpha(5.0, kControlDt);
  const double filtered = unfiltered * alpha / std::sqrt(2.0 - alpha);
  EXPECT_NEAR(velocity_rms(0.0), unfiltered, 0.05 * unfiltered);  // ~28 mm/s
  EXPECT_NEAR(velocity_rms(5.0), filtered, 0.05 * filtered);      // ~6 mm/s
  // unfiltered it would cross the model reflex threshold (70 mm/s) at 2.5 sigma; filtered,
  // at more than 10 sigma
  EXPECT_LT(filtered, 0.1 * 0.070);
}

TEST(SensorSuite, DeterministicPerSeed) {
  // every field of both muscles over 2 s with a stretch, default noise
  auto trace = [](std::uint64_t seed) {
    Plant plant;
    SensorSuite suite(SensingConfig{}, plant.muscles, seed);
    std::vector<double> out;
    const auto readings = run(&suite, &plant, 200, [](int j, Plant* p) {
      if (j > 100 && j <= 105) p->d_m[0] += 0.150 * kControlDt;
    });
    for (const std::vector<MuscleReading>& tick : readings) {
      for (const MuscleReading& r : tick) {
        for (double v : fields(r)) out.push_back(v);
      }
    }
    return out;
  };
  EXPECT_EQ(trace(99), trace(99));
  EXPECT_NE(trace(99), trace(100));
}

TEST(SensorSuite, DrawsNoiseInTheDocumentedOrder) {
  // an independent equivalent: the three sensors of sensors.h on one generator seeded
  // alike, muscle by muscle, pressure then gauge then fiber
  Plant plant;
  const SensingConfig config;
  SensorSuite suite(config, plant.muscles, 42);
  std::mt19937_64 rng(42);
  PressureSensor pressure(config.sensors);
  std::vector<StrainGauge> gauges;
  std::vector<FiberSensor> fibers;
  for (const MuscleSensorSpec& m : plant.muscles) {
    gauges.emplace_back(m.gauge, config.sensors);
    fibers.emplace_back(config.sensors, kControlDt);
  }
  const auto readings = run(&suite, &plant, 20, [](int j, Plant* p) {
    if (j >= 10) p->d_m[0] += 0.150 * kControlDt;
  });
  Plant replay;
  for (int tick = 0; tick < 20; ++tick) {
    if (tick >= 10) replay.d_m[0] += 0.150 * kControlDt;
    const std::vector<MuscleTruth> truth = replay.truth();
    for (int j = 0; j < 2; ++j) {
      const double pressure_v = pressure.sample(truth[j].pressure_pa, rng).voltage_v;
      const double gauge_v = gauges[j].sample(truth[j].force_n, rng);
      const double fiber_rate = fibers[j].sample(truth[j].length_m, rng);
      EXPECT_EQ(readings[tick][j].pressure_sensor_v, pressure_v) << tick << " " << j;
      EXPECT_EQ(readings[tick][j].gauge_v, gauge_v) << tick << " " << j;
      EXPECT_EQ(readings[tick][j].fiber_rate_m_s, fiber_rate) << tick << " " << j;
    }
  }
}

TEST(SensorSuite, OneSensorsNoiseLevelLeavesTheOthersNoiseAlone) {
  // every sensor draws one normal per sample even at zero noise (sensors.h), so a sweep
  // that switches the fiber noise off sees the same pressure and gauge noise
  auto run_with_fiber_noise = [](double fiber_noise_mm_s) {
    SensingConfig config;
    config.sensors.fiber_noise_m_s = fiber_noise_mm_s * 1e-3;
    Plant plant;
    SensorSuite suite(config, plant.muscles, 11);
    return run(&suite, &plant, 50);
  };
  const auto noisy = run_with_fiber_noise(2.0);
  const auto quiet = run_with_fiber_noise(0.0);
  int fiber_differs = 0;
  for (std::size_t tick = 0; tick < noisy.size(); ++tick) {
    for (int j = 0; j < 2; ++j) {
      EXPECT_EQ(noisy[tick][j].pressure_sensor_v, quiet[tick][j].pressure_sensor_v);
      EXPECT_EQ(noisy[tick][j].gauge_v, quiet[tick][j].gauge_v);
      EXPECT_EQ(noisy[tick][j].velocity_est_m_s, quiet[tick][j].velocity_est_m_s);
      EXPECT_EQ(quiet[tick][j].fiber_rate_m_s, 0.0);
      fiber_differs += noisy[tick][j].fiber_rate_m_s != 0.0;
    }
  }
  EXPECT_EQ(fiber_differs, 100);
}

}  // namespace
}  // namespace pamsim
