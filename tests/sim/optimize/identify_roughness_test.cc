// identify_roughness_test.cc: the check of a model's numerical roughness and the intervals
// from secants (identify_uncertainty.h), on models whose answers are known in closed form:
//  - the roughness of a quadratic is |c| h / |b + 2 c u| exactly, and that of differences
//    that are independent noise tends to sqrt(3);
//  - on a linear model the secant over the interval is the derivative, so the errors are
//    fill_uncertainty's to rounding;
//  - on a line plus a lattice of independent jitter (a solver's error control as the
//    parameters move), the derivative at the difference step overstates the information
//    (its error too small by a factor over 1.5); the secants' comes back to within 15 % of
//    the line's own.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "sim/optimize/identify.h"
#include "sim/optimize/identify_residuals.h"
#include "sim/optimize/identify_uncertainty.h"

namespace pamsim {
namespace {

constexpr std::size_t kSamples = 2000;

// one linear parameter over [0, 1]: the result's single entry, value = u
IdentifyResult one_parameter() {
  IdentifyResult result;
  IdentifiedParameter p;
  p.parameter.key = "x";
  p.parameter.from = 0.0;
  p.parameter.to = 1.0;
  result.parameters.push_back(p);
  return result;
}

// residuals slope_i (u - 0.5) + noise_i + jitter_i(u): noise white with SD 0.1, fixed; the
// jitter, `amplitude` times a value drawn afresh in each cell of width `cell` (0: none)
struct LineModel {
  std::vector<double> slope, noise;
  double amplitude = 0.0, cell = 1.0;
  LineModel() {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> n01(0.0, 1.0);
    for (std::size_t i = 0; i < kSamples; ++i) {
      slope.push_back(1.0 + 0.5 * std::sin(0.01 * static_cast<double>(i)));
      noise.push_back(0.1 * n01(rng));
    }
  }
  std::vector<double> operator()(const std::vector<double>& unit) const {
    const auto k = static_cast<std::uint64_t>(std::llround(unit[0] / cell));
    std::mt19937_64 rng(k * 7919 + 13);
    std::normal_distribution<double> n01(0.0, 1.0);
    std::vector<double> r(kSamples);
    for (std::size_t i = 0; i < kSamples; ++i) {
      r[i] = slope[i] * (unit[0] - 0.5) + noise[i] + amplitude * n01(rng);
    }
    return r;
  }
};

// the Jacobian of central differences of kDifferenceStep at u = 0.5
Eigen::MatrixXd derivative(const LineModel& model) {
  const std::vector<double> plus = model({0.5 + kDifferenceStep});
  const std::vector<double> minus = model({0.5 - kDifferenceStep});
  Eigen::MatrixXd j(kSamples, 1);
  for (std::size_t i = 0; i < kSamples; ++i) {
    j(static_cast<Eigen::Index>(i), 0) = (plus[i] - minus[i]) / (2.0 * kDifferenceStep);
  }
  return j;
}

// the standard error from the derivative, then from the secants
std::pair<double, double> errors(const LineModel& model) {
  IdentifyResult result = one_parameter();
  const std::vector<double> at = model({0.5});
  const Eigen::VectorXd r = Eigen::Map<const Eigen::VectorXd>(at.data(), kSamples);
  const std::vector<std::size_t> segments = {kSamples};
  fill_uncertainty(derivative(model), r, segments, {0.5}, 0.95, &result);
  const double local = result.parameters[0].std_error;
  fill_interval_uncertainty(model, derivative(model), r, segments, {0.5}, 0.95, &result);
  return {local, result.parameters[0].std_error};
}

TEST(IdentifyRoughnessTest, AQuadraticsRoughnessIsItsClosedForm) {
  const double b = 2.0, c = -3.0, u = 0.3, h = 1e-3;
  auto r = [&](double x) {
    return std::vector<double>{b * x + c * x * x, 0.5 * (b * x + c * x * x)};
  };
  EXPECT_NEAR(difference_roughness(r(u - h), r(u), r(u + h)),
              std::abs(c) * h / std::abs(b + 2 * c * u), 1e-6);
  EXPECT_TRUE(std::isnan(difference_roughness({1.0, 2.0}, {1.0, 2.0}, {1.0, 2.0})));
}

TEST(IdentifyRoughnessTest, DifferencesOfIndependentNoiseGiveTheRootOfThree) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n01(0.0, 1.0);
  std::vector<double> a(20000), b(20000), c(20000);
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i] = n01(rng);
    b[i] = n01(rng);
    c[i] = n01(rng);
  }
  EXPECT_NEAR(difference_roughness(a, b, c), std::sqrt(3.0), 0.03);
  EXPECT_GT(difference_roughness(a, b, c), kRoughnessLimit);
}

TEST(IdentifyRoughnessTest, OnALinearModelTheSecantIsTheDerivative) {
  const LineModel line;
  const auto [local, secant] = errors(line);
  ASSERT_GT(local, 0.0);
  EXPECT_NEAR(secant / local, 1.0, 1e-6);
}

TEST(IdentifyRoughnessTest, SecantsUndoTheInformationAJitterPretends) {
  const LineModel line;
  const double truth = errors(line).first;
  LineModel rough;
  rough.amplitude = 0.002;  // a jitter of 0.02 noise SDs, fresh every 1e-4 of the box
  rough.cell = 1e-4;
  const auto [local, secant] = errors(rough);
  IdentifyResult result = one_parameter();
  fill_roughness(rough, {0.5}, &result);
  EXPECT_GT(result.parameters[0].roughness, kRoughnessLimit);
  EXPECT_LT(local, truth / 1.5) << "the derivative should overstate the information";
  EXPECT_NEAR(secant / truth, 1.0, 0.15);
}

TEST(IdentifyRoughnessTest, TheSecantsListEachCorrelationOnce) {
  // two parameters whose columns nearly coincide: correlated beyond 0.9, named once each
  const LineModel line;
  const ResidualsAt model = [&](const std::vector<double>& unit) {
    std::vector<double> r = line({unit[0]});
    for (std::size_t i = 0; i < kSamples; ++i) {
      r[i] += (1.0 + 0.01 * std::cos(0.3 * static_cast<double>(i))) * (unit[1] - 0.5);
    }
    return r;
  };
  IdentifyResult result = one_parameter();
  result.parameters.push_back(result.parameters[0]);
  result.parameters[1].parameter.key = "y";
  const std::vector<double> at = model({0.5, 0.5});
  const Eigen::VectorXd r = Eigen::Map<const Eigen::VectorXd>(at.data(), kSamples);
  Eigen::MatrixXd jacobian(kSamples, 2);
  for (std::size_t j = 0; j < 2; ++j) {
    std::vector<double> plus = {0.5, 0.5}, minus = {0.5, 0.5};
    plus[j] += kDifferenceStep;
    minus[j] -= kDifferenceStep;
    const std::vector<double> rp = model(plus), rm = model(minus);
    for (std::size_t i = 0; i < kSamples; ++i) {
      jacobian(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          (rp[i] - rm[i]) / (2.0 * kDifferenceStep);
    }
  }
  fill_uncertainty(jacobian, r, {kSamples}, {0.5, 0.5}, 0.95, &result);
  fill_interval_uncertainty(model, jacobian, r, {kSamples}, {0.5, 0.5}, 0.95, &result);
  ASSERT_EQ(result.parameters[0].correlated.size(), 1u);
  EXPECT_EQ(result.parameters[0].correlated[0].first, "y");
  ASSERT_EQ(result.parameters[1].correlated.size(), 1u);
  EXPECT_EQ(result.parameters[1].correlated[0].first, "x");
}

}  // namespace
}  // namespace pamsim
