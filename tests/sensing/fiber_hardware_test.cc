// fiber_hardware_test.cc: the fiber sensor as hardware (fiber_hardware.h) and the encoder's
// resolution (sensors.h) against closed forms: the fabric's nonlinearity at and around its
// span, its creep after a held stretch (Prony step response) and recovery, the FiberSensor
// integrating the fabric's reading so its length drifts by exactly that creep, the encoder's
// count step in the fiber's calibration; and every bad key is named.
#include "sensing/fiber_hardware.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sensing/sensors.h"
#include "sensing_test_util.h"
#include "base/control_step.h"
#include "base/no_value.h"

namespace pamsim {
namespace {

using pamsim_test::kControlDt;

FiberHardwareConfig fabric(double nonlinearity_pct, std::vector<PronyTerm> creep) {
  FiberHardwareConfig c;
  c.enabled = true;
  c.nonlinearity_pct = nonlinearity_pct;
  c.span_m = 0.020;
  c.creep = std::move(creep);
  return c;
}

TEST(FiberHardwareTest, NonlinearityIsItsPercentOfTheReadingAtTheSpan) {
  FiberHardware fiber(fabric(5.0, {}), kControlDt);
  // u (1 + 0.05 u / 20 mm): 5 % at +-20 mm, 2.5 % at 10 mm, quadratic, signed
  EXPECT_NEAR(fiber.reading_m(0.020), 0.021, 1e-15);
  EXPECT_NEAR(fiber.reading_m(0.010), 0.01025, 1e-15);
  EXPECT_NEAR(fiber.reading_m(-0.020), -0.019, 1e-15);
  EXPECT_DOUBLE_EQ(fiber.reading_m(0.0), 0.0);
  FiberHardware under(fabric(-5.0, {}), kControlDt);
  EXPECT_NEAR(under.reading_m(0.020), 0.019, 1e-15);
}

TEST(FiberHardwareTest, AHeldStretchCreepsAsThePronyStepAndRecovers) {
  const double g = 0.05, tau = 10.0, u = 0.008;
  FiberHardware fiber(fabric(0.0, {{g, tau}}), kControlDt);
  for (int n = 1; n <= 1000; ++n) {
    const double r = fiber.reading_m(u);
    EXPECT_NEAR(r, u * (1.0 + g * (1.0 - std::exp(-n * kControlDt / tau))), 1e-15) << n;
  }
  // released after 10 s: the creep recovers from g (1 - e^-1) as exp(-t / tau)
  const double crept = g * (1.0 - std::exp(-1.0));
  for (int n = 1; n <= 500; ++n) {
    EXPECT_NEAR(fiber.reading_m(0.0), u * crept * std::exp(-n * kControlDt / tau), 1e-15) << n;
  }
}

TEST(FiberHardwareTest, TheSensorsLengthDriftsByTheFabricsCreep) {
  SensorConfig config;
  config.fiber_noise_m_s = 0.0;
  config.fiber_hardware = fabric(0.0, {{0.05, 10.0}});
  FiberSensor fiber(config, kControlDt, FiberHardware(config.fiber_hardware, kControlDt));
  std::mt19937_64 rng(1);
  fiber.sample(0.160, rng);
  // stretched 8 mm in one tick and held 10 s: the integrated length reads the creep
  for (int n = 1; n <= 1000; ++n) fiber.sample(0.168, rng);
  const double drift = 0.008 * 0.05 * (1.0 - std::exp(-1.0));
  EXPECT_NEAR(fiber.length_m() - 0.168, drift, 1e-12);
  EXPECT_GT(drift, 2.5e-4);
}

TEST(EncoderTest, TheFiberIsCalibratedToTheEncodersCount) {
  SensorConfig config;
  config.fiber_noise_m_s = 0.0;
  config.encoder = {true, 1e-5};
  EXPECT_DOUBLE_EQ(encoder_read_m(config.encoder, 0.1600049), 0.16);
  EXPECT_DOUBLE_EQ(encoder_read_m(config.encoder, 0.1600051), 0.16001);
  EXPECT_DOUBLE_EQ(encoder_read_m(EncoderConfig{}, 0.1600049), 0.1600049);  // ideal
  // the count step: every reading on a multiple of 10 um, within half of it
  for (double l = 0.15; l < 0.17; l += 1.37e-6) {
    const double r = encoder_read_m(config.encoder, l);
    EXPECT_LE(std::fabs(r - l), 0.5e-5 + 1e-15);
    EXPECT_NEAR(r / 1e-5, std::round(r / 1e-5), 1e-6);
  }
  FiberSensor fiber(config, kControlDt);
  std::mt19937_64 rng(1);
  fiber.sample(0.1600049, rng);
  EXPECT_DOUBLE_EQ(fiber.length_m(), 0.16);
  // later changes are the fiber's own (the true rate here), from the counted start
  fiber.sample(0.1610049, rng);
  EXPECT_NEAR(fiber.length_m(), 0.161, 1e-12);
}

TEST(FiberHardwareTest, EveryBadKeyIsNamed) {
  using C = FiberHardwareConfig;
  const test::BadValueOf<C> cases[] = {
      {"sensors.fiber.nonlinearity_pct", "nan", [](C& c) { c.nonlinearity_pct = kNaN; }},
      {"sensors.fiber.nonlinearity_pct", "100", [](C& c) { c.nonlinearity_pct = 100; }},
      {"sensors.fiber.span_mm", "0", [](C& c) { c.span_m = 0; }},
      {"sensors.fiber.creep_weights[0]", "-0.1",
       [](C& c) {
         c.creep = {{-0.1, 1.0}};
       }},
      {"sensors.fiber.creep_times_s[0]", "0",
       [](C& c) {
         c.creep = {{0.1, 0.0}};
       }},
  };
  for (const auto& k : cases) {
    C c;
    k.set(c);
    test::expect_bad_value([&] { validate(c); }, k.key, k.value);
  }
  EXPECT_NO_THROW(validate(FiberHardwareConfig{}));
}

}  // namespace
}  // namespace pamsim
