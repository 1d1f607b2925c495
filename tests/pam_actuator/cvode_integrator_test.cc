// cvode_integrator_test.cc: tests for the CVODE wrapper (cvode_integrator.h): accuracy on
// an analytic ODE, stop-time stepping, exceptions from the right-hand side, reset.
#include "pam_actuator/cvode_integrator.h"

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
