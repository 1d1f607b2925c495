// bladder_relaxation_test.cc: the bladder's Prony relaxation (bladder_relaxation.h) against
// its closed forms: a ramp's overstress and its relaxation once held, the energy a sinusoid
// dissipates per cycle, the constant-loss spectrum's loss tangent, and bad terms named.
#include "pam_actuator/bladder_relaxation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "base/input_error.h"

namespace pamsim {
namespace {

constexpr double kPi = 3.14159265358979323846;

BladderRelaxation two_terms() {
  BladderRelaxation r;
  r.count = 2;
  r.weight = {0.1, 0.05};
  r.time_s = {0.02, 0.5};
  return r;
}

// A ramp of F_e at rate q for T, then held: h_i = g_i q tau_i (1 - exp(-t / tau_i)) during
// the ramp, then decaying as exp(-(t - T) / tau_i): the update is exact for a ramp, so to
// rounding at every step, whatever the step.
TEST(BladderRelaxationTest, ARampAndHoldFollowTheClosedFormAtEveryStep) {
  const BladderRelaxation r = two_terms();
  for (double dt : {1e-3, 7e-3}) {
    SCOPED_TRACE(dt);
    const RelaxationStep step = relaxation_step(r, dt);
    const double q = 250.0, ramp_s = 0.3;  // [N/s], [s]
    double h[kMaxRelaxationTerms] = {};
    const int ramp_steps = static_cast<int>(std::lround(ramp_s / dt));
    for (int k = 1; k <= 2 * ramp_steps; ++k) {
      const double change = k <= ramp_steps ? q * dt : 0.0;
      const double sum = relaxation_advance(r, step, h, change, h);
      const double t = k * dt, end = ramp_steps * dt;
      double expected = 0.0;
      for (int i = 0; i < r.count; ++i) {
        const double tau = r.time_s[i];
        const double at_end = r.weight[i] * q * tau * (1.0 - std::exp(-std::min(t, end) / tau));
        expected += t <= end ? at_end : at_end * std::exp(-(t - end) / tau);
      }
      ASSERT_NEAR(sum, expected, 1e-12 * (1.0 + std::fabs(expected))) << "step " << k;
    }
  }
}

// A step of F_e is answered with (1 + sum g_i) of it at once (dt << tau).
TEST(BladderRelaxationTest, AFastStepIsAnsweredWithTheInstantaneousModulus) {
  const BladderRelaxation r = two_terms();
  const RelaxationStep step = relaxation_step(r, 1e-7);
  double h[kMaxRelaxationTerms] = {};
  EXPECT_NEAR(relaxation_advance(r, step, h, 10.0, h), 10.0 * (0.1 + 0.05), 1e-5);
}

// Driven by F_e = A sin(w t) on a spring of relaxed stiffness k (x = F_e / k), the force
// F_e + sum h_i encloses pi A^2 G''(w) / k per cycle once the start has died away.
TEST(BladderRelaxationTest, ASinusoidDissipatesTheLossModulusPerCycle) {
  const BladderRelaxation r = two_terms();
  const double amplitude = 5.0, k = 2000.0;  // [N], [N/m]
  for (double hz : {0.5, 3.0, 12.0}) {
    SCOPED_TRACE(hz);
    const double omega = 2.0 * kPi * hz;
    const int per_cycle = 20000;
    const double dt = 1.0 / (hz * per_cycle);
    const RelaxationStep step = relaxation_step(r, dt);
    double h[kMaxRelaxationTerms] = {}, previous_fe = 0.0, previous_force = 0.0;
    double work = 0.0;
    const int cycles = 12;  // tau_max = 0.5 s: 12 cycles at 0.5 Hz leave e^-48 of the start
    for (int n = 1; n <= cycles * per_cycle; ++n) {
      const double fe = amplitude * std::sin(omega * n * dt);
      const double force = fe + relaxation_advance(r, step, h, fe - previous_fe, h);
      if (n > (cycles - 1) * per_cycle) {  // the last cycle: trapezoidal force dx
        work += 0.5 * (force + previous_force) * (fe - previous_fe) / k;
      }
      previous_fe = fe;
      previous_force = force;
    }
    const double expected = kPi * amplitude * amplitude * relaxation_loss_modulus(r, omega) / k;
    EXPECT_NEAR(work, expected, 1e-4 * expected);
  }
}

// One term per decade with g = (2 tan(delta) / pi) ln 10 holds tan(delta) = G'' / G' within
// the ripple of the discretization over the decades the terms span (Tschoegl's relation).
TEST(BladderRelaxationTest, OneTermPerDecadeHoldsAConstantLossTangentInItsBand) {
  const double tan_delta = 0.05;
  BladderRelaxation r;
  r.count = 4;
  const double g = 2.0 * tan_delta / kPi * std::log(10.0);
  r.weight = {g, g, g, g};
  r.time_s = {0.001, 0.01, 0.1, 1.0};
  for (double hz : {0.5, 1.0, 3.0, 10.0, 30.0}) {  // the terms span 0.16-160 Hz
    const double omega = 2.0 * kPi * hz;
    const double tangent = relaxation_loss_modulus(r, omega) / relaxation_storage_modulus(r, omega);
    EXPECT_NEAR(tangent, tan_delta, 0.25 * tan_delta) << hz << " Hz";
  }
}

TEST(BladderRelaxationTest, BadTermsAreNamedByTheirKeys) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    int term;
    double weight, time_s;
    const char* message;
  };
  for (const Case& c :
       {Case{0, -0.1, 0.1, "bladder.relaxation_weights[0] must be >= 0, got -0.1"},
        Case{1, 0.1, 0.0, "bladder.relaxation_times_s[1] must be > 0 s, got 0"},
        Case{1, nan, 0.1, "bladder.relaxation_weights[1] must be >= 0, got nan"},
        Case{0, 0.1, -2.0, "bladder.relaxation_times_s[0] must be > 0 s, got -2"}}) {
    BladderRelaxation r = two_terms();
    r.weight[c.term] = c.weight;
    r.time_s[c.term] = c.time_s;
    try {
      validate_bladder_relaxation(r, "bladder.");
      ADD_FAILURE() << c.message;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), c.message);
    }
  }
  BladderRelaxation too_many = two_terms();
  too_many.count = kMaxRelaxationTerms + 1;
  EXPECT_THROW(validate_bladder_relaxation(too_many, "bladder."), InputError);
  EXPECT_NO_THROW(validate_bladder_relaxation(BladderRelaxation{}, "bladder."));
}

}  // namespace
}  // namespace pamsim
