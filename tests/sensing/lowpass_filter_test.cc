// lowpass_filter_test.cc: the discretised first-order low-pass against its continuous
// step response, DC gain, first-sample initialisation and the off switch.
#include "sensing/lowpass_filter.h"
#include "base/units.h"

#include <cmath>

#include <gtest/gtest.h>

namespace pamsim {
namespace {

using units::kPi;

TEST(LowpassFilter, StepResponseMatchesContinuousAtSamples) {
  const double fc = 5.0;
  const double dt = 0.01;
  const double tau = 1.0 / (2.0 * kPi * fc);
  LowpassFilter filter(fc, dt);
  EXPECT_DOUBLE_EQ(filter.step(0.0), 0.0);  // initialises at 0
  for (int n = 1; n <= 100; ++n) {
    const double y = filter.step(1.0);  // unit step from sample 0 to 1
    EXPECT_NEAR(y, 1.0 - std::exp(-n * dt / tau), 1e-12) << "sample " << n;
  }
}

TEST(LowpassFilter, DcGainIsOne) {
  LowpassFilter filter(10.0, 0.01);
  for (int n = 0; n < 50; ++n) EXPECT_DOUBLE_EQ(filter.step(3.7), 3.7);
  // and a step settles to its new level
  double y = 0.0;
  for (int n = 0; n < 1000; ++n) y = filter.step(-2.5);
  EXPECT_NEAR(y, -2.5, 1e-12);
}

TEST(LowpassFilter, InitialisesToFirstSampleWithoutTransient) {
  LowpassFilter filter(1.0, 0.01);
  EXPECT_DOUBLE_EQ(filter.step(0.42e6), 0.42e6);
  EXPECT_DOUBLE_EQ(filter.step(0.42e6), 0.42e6);
  filter.reset();
  EXPECT_DOUBLE_EQ(filter.step(-1.0), -1.0);
}

TEST(LowpassFilter, ZeroCutoffPassesThrough) {
  LowpassFilter filter(0.0, 0.01);
  EXPECT_DOUBLE_EQ(filter.alpha(), 1.0);
  const double xs[] = {1.0, -3.0, 7.5, 0.0};
  for (double x : xs) EXPECT_DOUBLE_EQ(filter.step(x), x);
}

TEST(LowpassFilter, AlphaIsExactForThePeriod) {
  EXPECT_NEAR(lowpass_alpha(5.0, 0.01), 1.0 - std::exp(-2.0 * kPi * 5.0 * 0.01), 1e-15);
  // halving dt twice composes to the same decay over the same time
  const double a1 = lowpass_alpha(5.0, 0.01);
  const double a2 = lowpass_alpha(5.0, 0.005);
  EXPECT_NEAR(1.0 - a1, (1.0 - a2) * (1.0 - a2), 1e-15);
}

}  // namespace
}  // namespace pamsim
