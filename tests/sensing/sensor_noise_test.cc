// sensor_noise_test.cc: the noise primitives (sensor_noise.h): the Gauss-Markov process's
// stationary variance and autocorrelation at a lag against sigma^2 exp(-n dt / tau), its
// exact discretisation at a coarse step, rounding to a step, and derived generators that are
// fixed by their seed and tags and differ across them.
#include "sensing/sensor_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace pamsim {
namespace {

// the ensemble mean of b_k b_{k+lag} over many independent processes, and of b_k^2
struct Moments {
  double variance = 0.0;
  double lagged = 0.0;
};

Moments ensemble(double sigma, double tau, double dt, int k, int lag, int processes) {
  std::mt19937_64 rng(11);
  Moments m;
  for (int i = 0; i < processes; ++i) {
    GaussMarkov b(sigma, tau, dt, rng);
    for (int s = 0; s < k; ++s) b.step(rng);
    const double at_k = b.value();
    for (int s = 0; s < lag; ++s) b.step(rng);
    m.variance += at_k * at_k / processes;
    m.lagged += at_k * b.value() / processes;
  }
  return m;
}

TEST(GaussMarkovTest, StationaryVarianceAndAutocorrelationAtALag) {
  const double sigma = 2.0, tau = 0.5, dt = 0.01;
  const int n = 40000;
  const Moments m = ensemble(sigma, tau, dt, 20, 30, n);
  // E[b^2] = sigma^2 from the first sample on; the sample variance's SD is sigma^2 sqrt(2/n)
  EXPECT_NEAR(m.variance, sigma * sigma, 4.0 * sigma * sigma * std::sqrt(2.0 / n));
  // E[b_k b_{k+n}] = sigma^2 exp(-n dt / tau): exp(-0.6) = 0.549 of the variance
  const double expected = sigma * sigma * std::exp(-30 * dt / tau);
  EXPECT_NEAR(m.lagged, expected, 4.0 * sigma * sigma * std::sqrt(2.0 / n));
}

TEST(GaussMarkovTest, ExactAtAStepAsLongAsTheCorrelationTime) {
  // dt = tau: an Euler step would give phi = 0 and the wrong variance; the exact one
  // phi = exp(-1) and sigma^2 at every step
  const double sigma = 1.0, tau = 1.0;
  std::mt19937_64 rng(3);
  EXPECT_DOUBLE_EQ(GaussMarkov(sigma, tau, tau, rng).phi(), std::exp(-1.0));
  const int n = 40000;
  const Moments m = ensemble(sigma, tau, tau, 5, 1, n);
  EXPECT_NEAR(m.variance, 1.0, 4.0 * std::sqrt(2.0 / n));
  EXPECT_NEAR(m.lagged, std::exp(-1.0), 4.0 * std::sqrt(2.0 / n));
}

TEST(GaussMarkovTest, AZeroSigmaStaysAtZeroButStillDraws) {
  std::mt19937_64 a(5), b(5);
  GaussMarkov quiet(0.0, 1.0, 0.01, a);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(quiet.step(a), 0.0);
  // eleven draws taken, as a process with sigma > 0 would take
  for (int i = 0; i < 11; ++i) standard_normal(b);
  EXPECT_EQ(a(), b());
}

TEST(QuantiseTest, RoundsToTheNearestStep) {
  EXPECT_DOUBLE_EQ(quantise(0.0123, 0.01), 0.01);
  EXPECT_DOUBLE_EQ(quantise(0.0151, 0.01), 0.02);
  EXPECT_DOUBLE_EQ(quantise(-0.0151, 0.01), -0.02);
  EXPECT_DOUBLE_EQ(quantise(0.1234567, 0.0), 0.1234567);
  // within half a step everywhere, and on a multiple of it
  for (double x = -1.0; x < 1.0; x += 0.00137) {
    const double q = quantise(x, 1e-2);
    EXPECT_LE(std::fabs(q - x), 0.5e-2 + 1e-15);
    EXPECT_NEAR(q / 1e-2, std::round(q / 1e-2), 1e-9);
  }
}

std::vector<double> draws(std::mt19937_64 rng) {
  std::vector<double> out;
  for (int i = 0; i < 8; ++i) out.push_back(standard_normal(rng));
  return out;
}

TEST(DerivedGeneratorTest, FixedBySeedAndTagsAndDifferentAcrossThem) {
  EXPECT_EQ(draws(derived_generator(1, 1, 0)), draws(derived_generator(1, 1, 0)));
  EXPECT_NE(draws(derived_generator(1, 1, 0)), draws(derived_generator(2, 1, 0)));
  EXPECT_NE(draws(derived_generator(1, 1, 0)), draws(derived_generator(1, 2, 0)));
  EXPECT_NE(draws(derived_generator(1, 1, 0)), draws(derived_generator(1, 1, 1)));
  // the high half of a 64-bit seed counts too
  EXPECT_NE(draws(derived_generator(1, 1, 0)), draws(derived_generator(1 + (1ull << 32), 1, 0)));
  // and none is the trial's own stream
  EXPECT_NE(draws(derived_generator(1, 1, 0)), draws(std::mt19937_64(1)));
}

}  // namespace
}  // namespace pamsim
