// length_estimator_test.cc: Eq. (9)-(11) against the spring law itself (noise-free round
// trip), the slack behaviour of Fig. 7, Eq. (11) velocity, and the low-pass options.
#include "sensing/length_estimator.h"

#include <cmath>

#include <gtest/gtest.h>

#include "pam_actuator/spring_model.h"

namespace pamsim {
namespace {

// Table IV of Yoshida and Hosoda
SpringModel agonist_spring() {
  return spring_model_from_paper_units(SpringLaw::kEq3, -60.1, 170.1,
                                       {0.911, 0.256, 7.00, -0.201, 0, 0});
}
SpringModel antagonist_spring() {
  return spring_model_from_paper_units(SpringLaw::kEq3, -70.3, 178.5,
                                       {22.4, -0.129, 1.24, 0.871, 0, 0});
}

LengthEstimatorParams no_filters() {
  LengthEstimatorParams p;
  p.pressure_lowpass_hz = 0.0;
  p.velocity_lowpass_hz = 0.0;
  return p;
}

double gauge_voltage(const StrainGaugeParams& g, double f) { return g.q_v_per_n * f + g.v_base_v; }

TEST(LengthEstimator, NoiseFreeRoundTripEqualsSpringLaw) {
  const StrainGaugeParams gauge{2.25e-3, 0.05};
  for (const SpringModel& spring : {agonist_spring(), antagonist_spring()}) {
    for (double p : {0.2e6, 0.4e6, 0.6e6}) {
      for (double d : {0.5e-3, 2.0e-3, 6.66e-3, 12.0e-3}) {
        LengthEstimator est(spring, gauge, no_filters(), 0.01);
        const double f = spring_force(spring, p, d);
        ASSERT_GT(f, 0.0);
        const LengthEstimate e = est.update(p, gauge_voltage(gauge, f));
        EXPECT_EQ(e.status, InversionStatus::kOk);
        EXPECT_NEAR(e.force_n, f, 1e-9);
        EXPECT_NEAR(e.d_m, d, 1e-9) << "p " << p << " d " << d;
        EXPECT_NEAR(e.length_m, natural_length(spring, p) + d, 1e-9);
      }
    }
  }
}

TEST(LengthEstimator, SlackLineGivesNaturalLength) {
  const StrainGaugeParams gauge{4.33e-3, 0.2};
  LengthEstimator est(antagonist_spring(), gauge, no_filters(), 0.01);
  // the gauge reads V_base (zero tension) or a little below it (noise)
  for (double v : {0.2, 0.2 - 1e-4}) {
    const LengthEstimate e = est.update(0.4e6, v);
    EXPECT_EQ(e.status, InversionStatus::kSlack);
    EXPECT_DOUBLE_EQ(e.d_m, 0.0);
    EXPECT_DOUBLE_EQ(e.length_m, natural_length(antagonist_spring(), 0.4e6));
  }
}

TEST(LengthEstimator, VelocityIsEq11BackwardDifference) {
  const StrainGaugeParams gauge{2.25e-3, 0.0};
  const SpringModel spring = agonist_spring();
  const double dt = 0.01;
  LengthEstimator est(spring, gauge, no_filters(), dt);
  double last_l = 0.0;
  for (int j = 0; j < 30; ++j) {
    // pressure and deformation both change: l = l_n(p) + d
    const double p = 0.4e6 + 2e3 * j;
    const double d = 5e-3 + 0.8e-3 * j + 0.05e-3 * j * j;
    const LengthEstimate e = est.update(p, gauge_voltage(gauge, spring_force(spring, p, d)));
    const double l = natural_length(spring, p) + d;
    EXPECT_NEAR(e.length_m, l, 1e-9);
    if (j == 0) {
      EXPECT_DOUBLE_EQ(e.velocity_m_s, 0.0);
    } else {
      EXPECT_NEAR(e.velocity_m_s, (l - last_l) / dt, 1e-6);
    }
    last_l = l;
  }
}

TEST(LengthEstimator, SlackingShowsAsShortening) {
  // Fig. 7: when the line slackens the estimate falls to l_n, a negative velocity, never a
  // stretch
  const StrainGaugeParams gauge{2.25e-3, 0.0};
  const SpringModel spring = agonist_spring();
  LengthEstimator est(spring, gauge, no_filters(), 0.01);
  est.update(0.4e6, gauge_voltage(gauge, spring_force(spring, 0.4e6, 3e-3)));
  const LengthEstimate e = est.update(0.4e6, 0.0);
  EXPECT_NEAR(e.velocity_m_s, -3e-3 / 0.01, 1e-9);
}

TEST(LengthEstimator, PressureLowpassFiltersBeforeInversion) {
  const StrainGaugeParams gauge{2.25e-3, 0.0};
  const SpringModel spring = agonist_spring();
  LengthEstimatorParams params = no_filters();
  params.pressure_lowpass_hz = 5.0;
  LengthEstimator est(spring, gauge, params, 0.01);
  const double v = gauge_voltage(gauge, 30.0);
  // first sample: no transient
  EXPECT_DOUBLE_EQ(est.update(0.4e6, v).pressure_pa, 0.4e6);
  // a 0.1 MPa step reaches 1 - exp(-2 pi 5 0.01) of its size after one tick
  const double alpha = 1.0 - std::exp(-2.0 * 3.14159265358979323846 * 5.0 * 0.01);
  const LengthEstimate e = est.update(0.5e6, v);
  EXPECT_NEAR(e.pressure_pa, 0.4e6 + alpha * 0.1e6, 1e-6);
  EXPECT_NEAR(
      e.length_m,
      natural_length(spring, e.pressure_pa) + invert_spring_model(spring, e.pressure_pa, 30.0).d_m,
      1e-12);
}

TEST(LengthEstimator, VelocityLowpassSmoothsEq11) {
  const StrainGaugeParams gauge{2.25e-3, 0.0};
  const SpringModel spring = agonist_spring();
  LengthEstimatorParams params = no_filters();
  params.velocity_lowpass_hz = 10.0;
  const double dt = 0.01;
  LengthEstimator est(spring, gauge, params, dt);
  const double alpha = 1.0 - std::exp(-2.0 * 3.14159265358979323846 * 10.0 * dt);
  // at rest, then a ramp at 100 mm/s: the raw velocity steps 0 -> 0.1 m/s
  est.update(0.4e6, gauge_voltage(gauge, spring_force(spring, 0.4e6, 5e-3)));
  for (int n = 1; n <= 10; ++n) {
    const double d = 5e-3 + 0.1 * dt * n;
    const LengthEstimate e =
        est.update(0.4e6, gauge_voltage(gauge, spring_force(spring, 0.4e6, d)));
    EXPECT_NEAR(e.velocity_m_s, 0.1 * (1.0 - std::pow(1.0 - alpha, n)), 1e-6) << n;
  }
}

TEST(LengthEstimator, NoPhysicalRootHoldsLastDeformation) {
  // the agonist's law bends over above 1.27 MPa (a3 p + a1 < 0): at 1.5 MPa it cannot
  // produce more than ~716 N
  const StrainGaugeParams gauge{2.25e-3, 0.0};
  const SpringModel spring = agonist_spring();
  const double p = 1.5e6;
  LengthEstimator est(spring, gauge, no_filters(), 0.01);
  const double d0 = 4e-3;
  EXPECT_NEAR(est.update(p, gauge_voltage(gauge, spring_force(spring, p, d0))).d_m, d0, 1e-9);
  ASSERT_EQ(invert_spring_model(spring, p, 1000.0).status, InversionStatus::kNoPhysicalRoot);
  const LengthEstimate e = est.update(p, gauge_voltage(gauge, 1000.0));
  EXPECT_EQ(e.status, InversionStatus::kNoPhysicalRoot);
  EXPECT_NEAR(e.d_m, d0, 1e-9);
  EXPECT_NEAR(e.velocity_m_s, 0.0, 1e-9);
}

}  // namespace
}  // namespace pamsim
