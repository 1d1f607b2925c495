// residual_statistics_test.cc: the residual statistics (sim/optimize/residual_statistics.h)
// against closed forms and known rates: on a straight-line fit to AR(1) noise the sandwich
// covariance agrees with the estimate's true covariance (B X^T Sigma X B, Sigma_ij =
// phi^|i-j| / (1 - phi^2)) and its 95 % intervals cover the truth about 91 % of the time
// (365 of 400 at phi = 0.8, n = 400: the finite-sample shortfall every HAC estimator has
// there), where the plain s^2 (J^T J)^-1 ones cover half (200 of 400); the Ljung-Box test's
// false-alarm rate on white noise is its level, and it sees AR(1) residuals; the noise floor of a
// smooth signal plus white noise is the noise's sigma.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "base/portable_random.h"
#include "sim/optimize/residual_statistics.h"

namespace pamsim {
namespace {

constexpr double kPhi = 0.8;
constexpr int kSeriesSamples = 400;

// AR(1) noise of unit innovations, started in its stationary distribution
Eigen::VectorXd ar1(std::mt19937_64& rng, double phi, int n) {
  Eigen::VectorXd e(n);
  e[0] = portable_standard_normal(rng) / std::sqrt(1.0 - phi * phi);
  for (int t = 1; t < n; ++t) e[t] = phi * e[t - 1] + portable_standard_normal(rng);
  return e;
}

// the design of a straight line over [0, 1]: intercept and slope
Eigen::MatrixXd line_design(int n) {
  Eigen::MatrixXd x(n, 2);
  for (int t = 0; t < n; ++t) x.row(t) << 1.0, static_cast<double>(t) / (n - 1);
  return x;
}

TEST(ResidualStatisticsTest, SandwichMatchesTheClosedFormAndCoversUnderAr1Noise) {
  const Eigen::MatrixXd x = line_design(kSeriesSamples);
  Eigen::MatrixXd sigma(kSeriesSamples, kSeriesSamples);
  for (int i = 0; i < kSeriesSamples; ++i) {
    for (int j = 0; j < kSeriesSamples; ++j) {
      sigma(i, j) = std::pow(kPhi, std::abs(i - j)) / (1.0 - kPhi * kPhi);
    }
  }
  const Eigen::MatrixXd bread = (x.transpose() * x).inverse();
  const Eigen::MatrixXd truth = bread * x.transpose() * sigma * x * bread;
  const Eigen::Vector2d beta(1.0, -2.0);
  std::mt19937_64 rng(7);
  const int trials = 400;
  int hac_covered = 0, plain_covered = 0;
  double hac_variance = 0.0;
  for (int k = 0; k < trials; ++k) {
    const Eigen::VectorXd y = x * beta + ar1(rng, kPhi, kSeriesSamples);
    const Eigen::Vector2d fit = bread * x.transpose() * y;
    // the residuals' Jacobian with respect to the parameters is -X; the sign cancels
    const Eigen::VectorXd r = y - x * fit;
    const std::vector<std::size_t> one = {static_cast<std::size_t>(kSeriesSamples)};
    const std::vector<double> rv(r.data(), r.data() + r.size());
    const int lags = bartlett_bandwidth(pooled_lag1_autocorrelation(rv, one), rv.size());
    const Eigen::MatrixXd hac = hac_covariance(x, r, one, lags);
    const Eigen::MatrixXd plain = plain_covariance(x, r);
    ASSERT_EQ(hac.rows(), 2);
    hac_variance += hac(1, 1) / trials;
    hac_covered += std::fabs(fit[1] - beta[1]) <= 1.96 * std::sqrt(hac(1, 1));
    plain_covered += std::fabs(fit[1] - beta[1]) <= 1.96 * std::sqrt(plain(1, 1));
  }
  RecordProperty("hac_over_true_variance", std::to_string(hac_variance / truth(1, 1)));
  RecordProperty("hac_covered", hac_covered);
  RecordProperty("plain_covered", plain_covered);
  // prewhitened, within a few percent of the truth on average (0.945 measured)
  EXPECT_GT(hac_variance / truth(1, 1), 0.85);
  EXPECT_LT(hac_variance / truth(1, 1), 1.1);
  EXPECT_GE(hac_covered, static_cast<int>(0.88 * trials)) << plain_covered;
  EXPECT_LT(plain_covered, static_cast<int>(0.75 * trials)) << hac_covered;
}

TEST(ResidualStatisticsTest, ForIndependentResidualsTheSandwichIsThePlainCovariance) {
  const Eigen::MatrixXd x = line_design(kSeriesSamples);
  std::mt19937_64 rng(3);
  Eigen::VectorXd r(kSeriesSamples);
  for (int t = 0; t < kSeriesSamples; ++t) r[t] = portable_standard_normal(rng);
  const Eigen::MatrixXd hac = hac_covariance(x, r, {static_cast<std::size_t>(kSeriesSamples)}, 0);
  const Eigen::MatrixXd plain = plain_covariance(x, r);
  // with no lags, the sandwich is the White estimator: close to the plain one for i.i.d. noise
  EXPECT_NEAR(hac(1, 1) / plain(1, 1), 1.0, 0.25);
  EXPECT_EQ(bartlett_bandwidth(-0.1, 1000), 0);
  EXPECT_LT(bartlett_bandwidth(0.3, 1000), bartlett_bandwidth(0.8, 1000));
  EXPECT_LE(bartlett_bandwidth(0.999, 100), 25);
  EXPECT_EQ(hac_covariance(Eigen::MatrixXd::Zero(10, 2), Eigen::VectorXd::Ones(10), {10}, 1).size(),
            0);
}

TEST(ResidualStatisticsTest, EachSeriesKeepsItsOwnBandwidth) {
  // two series of one fit: a white one of unit noise that carries the first parameter (its
  // mean) and an AR(1) one, phi = 0.8, of innovations 0.03, that carries the second. Their
  // lag-1 autocorrelation pooled is near 0, often a bandwidth of 0, which leaves the second
  // parameter's variance about (1 + phi) / (1 - phi) = 9 times too small (about half of it on
  // average over these draws); each series' own bandwidth keeps it.
  const int n = kSeriesSamples;
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(2 * n, 2);
  x.topRows(n).col(0).setOnes();
  x.bottomRows(n).col(1).setOnes();
  const std::vector<std::size_t> series(2, static_cast<std::size_t>(n));
  // the second mean's true variance: the AR(1)'s long-run variance over n, about
  // 0.03^2 / (1 - phi)^2 / n
  double truth = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      truth += 0.03 * 0.03 * std::pow(kPhi, std::abs(i - j)) / (1 - kPhi * kPhi);
    }
  }
  truth /= static_cast<double>(n) * n;
  std::mt19937_64 rng(5);
  const int trials = 300;
  double own = 0.0, pooled = 0.0;
  for (int k = 0; k < trials; ++k) {
    Eigen::VectorXd e(2 * n);
    for (int t = 0; t < n; ++t) e[t] = portable_standard_normal(rng);
    e.tail(n) = 0.03 * ar1(rng, kPhi, n);
    const Eigen::VectorXd r = e - x * ((x.transpose() * x).inverse() * x.transpose() * e);
    const std::vector<double> rv(r.data(), r.data() + r.size());
    own += hac_covariance(x, r, series, segment_bandwidths(rv, series))(1, 1) / trials;
    const int lags = bartlett_bandwidth(pooled_lag1_autocorrelation(rv, series), rv.size());
    pooled += hac_covariance(x, r, series, lags)(1, 1) / trials;
  }
  RecordProperty("own_over_true_variance", std::to_string(own / truth));
  RecordProperty("pooled_over_true_variance", std::to_string(pooled / truth));
  EXPECT_GT(own / truth, 0.8);
  EXPECT_LT(own / truth, 1.2);
  EXPECT_LT(pooled / truth, 0.7);
  EXPECT_EQ(hac_covariance(x, Eigen::VectorXd::Ones(2 * n), {}, std::vector<int>{}).size(), 0)
      << "no series: no covariance, and no read past an empty list of bandwidths";
}

TEST(ResidualStatisticsTest, LjungBoxFalseAlarmRateIsItsLevelAndItSeesAr1) {
  std::mt19937_64 rng(11);
  int false_alarms = 0, detected = 0;
  const int series = 1000;
  for (int k = 0; k < series; ++k) {
    std::vector<double> white(200);
    for (double& v : white) v = portable_standard_normal(rng);
    false_alarms += ljung_box(white).p_value < 0.05;
    const Eigen::VectorXd e = ar1(rng, 0.5, 200);
    detected += ljung_box(std::vector<double>(e.data(), e.data() + e.size())).p_value < 0.05;
  }
  // 5 % of 1000: binomial sd 0.7 %, the band +-2.9 sd
  EXPECT_GE(false_alarms, 30);
  EXPECT_LE(false_alarms, 70);
  EXPECT_GE(detected, 990);
}

TEST(ResidualStatisticsTest, NoiseFloorOfASmoothSignalIsItsNoise) {
  std::mt19937_64 rng(5);
  std::vector<double> smooth(2000), noisy(2000);
  for (std::size_t t = 0; t < smooth.size(); ++t) {
    smooth[t] = 10.0 * std::sin(2.0 * 3.14159265358979 * static_cast<double>(t) / 200.0);
    noisy[t] = smooth[t] + 0.1 * portable_standard_normal(rng);
  }
  EXPECT_NEAR(noise_floor(noisy), 0.1, 0.006);
  // the sine's own second differences, at most 10 (2 pi / 200)^2, bound its floor
  const double curvature = 10.0 * std::pow(2.0 * 3.14159265358979 / 200.0, 2);
  EXPECT_LT(noise_floor(smooth), 1.4826 * curvature / std::sqrt(6.0));
  noisy[100] = noisy[500] = std::nan("");  // gaps are skipped
  EXPECT_NEAR(noise_floor(noisy), 0.1, 0.006);
  EXPECT_TRUE(std::isnan(noise_floor({1.0, 2.0, 3.0})));
}

}  // namespace
}  // namespace pamsim
