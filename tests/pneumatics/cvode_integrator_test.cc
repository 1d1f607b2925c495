// cvode_integrator_test.cc: tests for the CVODE wrapper (cvode_integrator.h): accuracy on
// an analytic ODE, stop-time stepping, exceptions from the right-hand side, reset.
#include "pneumatics/cvode_integrator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace pamsim {
namespace {

// y0' = -y0 / 0.1 (decay), y1' = 2 t (y1 = t^2): both analytic
class DecayAndRamp : public OdeSystem {
 public:
  int size() const override { return 2; }
  void rhs(double t, const double* y, double* ydot) override {
    ++calls;
    if (throw_after >= 0 && calls > throw_after) throw std::domain_error("boom in rhs");
    if (recoverable_once && y[0] < 0.5) {
      recoverable_once = false;
      throw RecoverableRhsError("retry");
    }
    ydot[0] = -y[0] / 0.1;
    ydot[1] = 2.0 * t;
  }
  long calls = 0;
  long throw_after = -1;
  bool recoverable_once = false;
};

TEST(CvodeIntegratorTest, MatchesAnalyticSolutionAtEveryStop) {
  DecayAndRamp ode;
  CvodeOptions options;
  options.relative_tolerance = 1e-10;
  options.absolute_tolerance = 1e-12;
  CvodeIntegrator integrator(ode, options, 0.0, {1.0, 0.0});
  for (int k = 1; k <= 500; ++k) {
    const double t = 1e-3 * k;
    integrator.advance_to(t);
    ASSERT_EQ(integrator.time(), t);
    EXPECT_NEAR(integrator.state()[0], std::exp(-t / 0.1), 1e-8);
    EXPECT_NEAR(integrator.state()[1], t * t, 1e-8);
  }
  EXPECT_GE(integrator.steps(), 500);  // the stop time bounds every step by 1 ms
  EXPECT_GT(integrator.rhs_evals(), integrator.steps());
}

// Four independent damped oscillators, each a block of two states (x' = v, v' = -w^2 x -
// 2 z w v, each its own w): a banded Jacobian when the system says so
class Oscillators : public OdeSystem {
 public:
  explicit Oscillators(bool banded) : banded_(banded) {}
  int size() const override { return 8; }
  int half_bandwidth() const override { return banded_ ? 1 : size() - 1; }
  void rhs(double, const double* y, double* ydot) override {
    for (int k = 0; k < 4; ++k) {
      const double w = omega(k);
      ydot[2 * k] = y[2 * k + 1];
      ydot[2 * k + 1] = -w * w * y[2 * k] - 2.0 * kDamping * w * y[2 * k + 1];
    }
  }
  static double omega(int k) { return 20.0 + 15.0 * k; }
  // x(t) from x(0) = 1, v(0) = 0 (under-damped)
  static double x(int k, double t) {
    const double w = omega(k), wd = w * std::sqrt(1.0 - kDamping * kDamping);
    return std::exp(-kDamping * w * t) * (std::cos(wd * t) + kDamping * w / wd * std::sin(wd * t));
  }
  static constexpr double kDamping = 0.3;

 private:
  bool banded_;
};

TEST(CvodeIntegratorTest, ABandedSystemSolvesAsTheDenseOneForFewerRightHandSides) {
  CvodeOptions options;
  options.relative_tolerance = 1e-10;
  options.absolute_tolerance = 1e-12;
  const std::vector<double> y0 = {1, 0, 1, 0, 1, 0, 1, 0};
  Oscillators banded(true), dense(false);
  CvodeIntegrator band_run(banded, options, 0.0, y0), dense_run(dense, options, 0.0, y0);
  for (int step = 1; step <= 200; ++step) {
    const double t = 1e-3 * step;
    band_run.advance_to(t);
    dense_run.advance_to(t);
    for (int k = 0; k < 4; ++k) {
      ASSERT_NEAR(band_run.state()[2 * k], Oscillators::x(k, t), 1e-7) << k << " at " << t;
      ASSERT_NEAR(dense_run.state()[2 * k], Oscillators::x(k, t), 1e-7) << k << " at " << t;
    }
  }
  // the difference quotients of a band of 1 take 3 right-hand sides, a dense 8 x 8 takes 8
  ASSERT_GT(band_run.jacobian_evals(), 0);
  const double band_per_jacobian =
      static_cast<double>(band_run.rhs_evals()) / static_cast<double>(band_run.jacobian_evals());
  const double dense_per_jacobian =
      static_cast<double>(dense_run.rhs_evals()) / static_cast<double>(dense_run.jacobian_evals());
  EXPECT_LT(band_per_jacobian + 4.0, dense_per_jacobian);
}

TEST(CvodeIntegratorTest, AdamsAlsoWorks) {
  DecayAndRamp ode;
  CvodeOptions options;
  options.method = CvodeMethod::kAdams;
  options.relative_tolerance = 1e-10;
  options.absolute_tolerance = 1e-12;
  CvodeIntegrator integrator(ode, options, 0.0, {1.0, 0.0});
  integrator.advance_to(0.3);
  EXPECT_NEAR(integrator.state()[0], std::exp(-3.0), 1e-8);
}

TEST(CvodeIntegratorTest, ExceptionInRhsBecomesIntegrationError) {
  DecayAndRamp ode;
  CvodeOptions options;
  options.absolute_tolerance = 1e-10;
  CvodeIntegrator integrator(ode, options, 0.0, {1.0, 0.0});
  integrator.advance_to(0.01);
  ode.throw_after = ode.calls + 3;
  try {
    integrator.advance_to(0.5);
    FAIL() << "no exception";
  } catch (const IntegrationError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("CVode failed"), std::string::npos) << m;
    EXPECT_NE(m.find("boom in rhs"), std::string::npos) << m;
  }
  // usable again after a reset
  ode.throw_after = -1;
  integrator.reset(0.0, {1.0, 0.0});
  integrator.advance_to(0.1);
  EXPECT_NEAR(integrator.state()[0], std::exp(-1.0), 1e-4);
}

TEST(CvodeIntegratorTest, RecoverableRhsErrorRetries) {
  DecayAndRamp ode;
  ode.recoverable_once = true;
  CvodeOptions options;
  options.absolute_tolerance = 1e-10;
  CvodeIntegrator integrator(ode, options, 0.0, {1.0, 0.0});
  integrator.advance_to(0.2);
  EXPECT_FALSE(ode.recoverable_once);
  EXPECT_NEAR(integrator.state()[0], std::exp(-2.0), 1e-5);
}

TEST(CvodeIntegratorTest, RejectsBadArguments) {
  DecayAndRamp ode;
  EXPECT_THROW(CvodeIntegrator(ode, CvodeOptions{}, 0.0, {1.0}), IntegrationError);
  CvodeIntegrator integrator(ode, CvodeOptions{}, 0.0, {1.0, 0.0});
  integrator.advance_to(0.1);
  EXPECT_THROW(integrator.advance_to(0.05), IntegrationError);
  EXPECT_NO_THROW(integrator.advance_to(0.1));  // no-op
  CvodeOptions bad;
  bad.relative_tolerance = -1.0;
  EXPECT_THROW(CvodeIntegrator(ode, bad, 0.0, {1.0, 0.0}), IntegrationError);
}

}  // namespace
}  // namespace pamsim
