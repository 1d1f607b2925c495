// spring_model_test.cc: Eq. (1)-(5) of Yoshida and Hosoda, unit conversion and inversion.
#include "pam_actuator/spring_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "pam_actuator/identification.h"
#include "base/input_error.h"
#include "pam_actuator/tensile_test.h"
#include "pam_actuator/table4_springs.h"

namespace pamsim {
namespace {

using pamsim_test::table4_agonist;
using pamsim_test::table4_antagonist;

// Eq. (4) and (5) sets fitted to a noise-free virtual tensile test of the agonist law
SpringModel fitted(SpringLaw law, const SpringModel& truth) {
  TensileTestOptions options;
  options.max_deformation_mm = 30.0;
  options.pressures_mpa = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8};
  return fit_spring_model(law, run_tensile_test(truth, options), "fit").model;
}

TEST(SpringModelTest, Table4AgonistForceMatchesHandComputation) {
  // Eq. (3) at p = 0.4 MPa, d = 10 mm: (-0.201*0.4*10 + 7*0.4 + 0.256*10 + 0.911) * 10
  const double expected = (-0.201 * 0.4 * 10 + 7.00 * 0.4 + 0.256 * 10 + 0.911) * 10;
  EXPECT_NEAR(expected, 54.67, 1e-12);
  EXPECT_NEAR(spring_force(table4_agonist(), 0.4e6, 10e-3), 54.67, 54.67 * 1e-9);
}

TEST(SpringModelTest, NaturalLengthIsEq2InSi) {
  // l_n = -60.1 mm/MPa * 0.4 MPa + 170.1 mm = 146.06 mm
  EXPECT_NEAR(natural_length(table4_agonist(), 0.4e6), 0.14606, 1e-12);
}

TEST(SpringModelTest, SlackLineGivesZeroForceAndStiffness) {
  for (double d : {0.0, -1e-3, -0.1}) {
    EXPECT_EQ(spring_force(table4_agonist(), 0.4e6, d), 0.0);
    EXPECT_EQ(spring_stiffness(table4_agonist(), 0.4e6, d), 0.0);
  }
}

TEST(SpringModelTest, StiffnessMatchesFiniteDifference) {
  const std::array<double, 6> eq4 = {0.911, 0.256, 7.00, 0.002, -0.201, 1.5};
  const std::array<double, 6> eq5 = {3.0, 0.005, 0.01, 0.5, 10.0, 0.0};
  const std::vector<SpringModel> models = {
      table4_agonist(), table4_antagonist(),
      spring_model_from_paper_units(SpringLaw::kEq4, 0, 170, eq4),
      spring_model_from_paper_units(SpringLaw::kEq5, 0, 170, eq5)};
  for (const SpringModel& model : models) {
    for (double p : {0.1e6, 0.45e6, 0.8e6}) {
      for (double d : {1e-3, 10e-3, 25e-3}) {
        const double h = 1e-7;
        const double fd = (spring_force(model, p, d + h) - spring_force(model, p, d - h)) / (2 * h);
        EXPECT_NEAR(spring_stiffness(model, p, d), fd, 1e-6 * std::abs(fd) + 1e-6);
      }
    }
  }
}

TEST(SpringModelTest, PaperSiConversionRoundTrip) {
  for (SpringLaw law : {SpringLaw::kEq3, SpringLaw::kEq4, SpringLaw::kEq5}) {
    const std::array<double, 6> paper = {1.5, -2.25, 3.125, 4.0, -5.5, 6.75};
    std::array<double, 6> in{};
    for (int k = 0; k < coefficient_count(law); ++k) in[k] = paper[k];
    const SpringModel model = spring_model_from_paper_units(law, -60.1, 170.1, in);
    double m = 0, h = 0;
    std::array<double, 6> out{};
    spring_model_to_paper_units(model, &m, &h, &out);
    EXPECT_NEAR(m, -60.1, 1e-12);
    EXPECT_NEAR(h, 170.1, 1e-12);
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(out[k], in[k], 1e-12 * (1 + std::abs(in[k])));
  }
}

TEST(SpringModelTest, SiForceEqualsPaperForceForEveryTerm) {
  // one coefficient at a time: SI evaluation must equal c p_MPa^i d_mm^(j+1)
  for (SpringLaw law : {SpringLaw::kEq3, SpringLaw::kEq4, SpringLaw::kEq5}) {
    for (int k = 0; k < coefficient_count(law); ++k) {
      std::array<double, 6> c{};
      c[k] = 1.7;
      const SpringModel model = spring_model_from_paper_units(law, 0, 100, c);
      const double p_mpa = 0.55, d_mm = 12.5;
      const double expected = 1.7 * std::pow(p_mpa, pressure_exponent(law, k)) *
                              std::pow(d_mm, deformation_exponent(law, k) + 1);
      EXPECT_NEAR(spring_force(model, p_mpa * 1e6, d_mm * 1e-3), expected, 1e-12 * expected)
          << coefficient_name(law, k);
    }
  }
}

TEST(SpringModelTest, NamesAndParsing) {
  EXPECT_EQ(coefficient_name(SpringLaw::kEq4, 5), "b5");
  EXPECT_EQ(coefficient_name(SpringLaw::kEq5, 0), "c0");
  EXPECT_EQ(parse_spring_law("eq5", "ctx"), SpringLaw::kEq5);
  EXPECT_THROW(parse_spring_law("eq6", "ctx"), InputError);
  EXPECT_STREQ(to_string(InversionStatus::kNoPhysicalRoot), "no_physical_root");
}

// f -> d -> f over the working range; d recovered to 1e-9 relative where f is monotone
void expect_round_trip(const SpringModel& model) {
  int checked = 0;
  for (double p_mpa = 0.1; p_mpa <= 0.8 + 1e-9; p_mpa += 0.05) {
    const double p = p_mpa * 1e6;
    for (double d_mm = 0.5; d_mm <= 30.0 + 1e-9; d_mm += 0.5) {
      const double d = d_mm * 1e-3;
      // the smallest positive root is d only if f rises on (0, d]
      bool monotone = true;
      for (double s = d / 200; s <= d; s += d / 200) {
        monotone = monotone && spring_stiffness(model, p, s) > 0.0;
      }
      if (!monotone) continue;
      const DeformationEstimate e = invert_spring_model(model, p, spring_force(model, p, d));
      ASSERT_EQ(e.status, InversionStatus::kOk) << "p " << p_mpa << " d " << d_mm;
      EXPECT_NEAR(e.d_m, d, 1e-9 * d) << "p " << p_mpa << " d " << d_mm;
      ++checked;
    }
  }
  EXPECT_GT(checked, 15 * 60 * 9 / 10);  // most of the working range is monotone
}

TEST(SpringModelTest, RoundTripTable4Eq3) {
  expect_round_trip(table4_agonist());
  expect_round_trip(table4_antagonist());
}

TEST(SpringModelTest, RoundTripFittedEq4AndEq5) {
  const SpringModel eq4 = fitted(SpringLaw::kEq4, table4_agonist());
  const SpringModel eq5 = fitted(SpringLaw::kEq5, table4_agonist());
  // the cubic path is really exercised: the d^3 coefficient is non-zero
  EXPECT_NE(deformation_polynomial(eq5, 0.4e6)[2], 0.0);
  expect_round_trip(eq4);
  expect_round_trip(eq5);
  expect_round_trip(fitted(SpringLaw::kEq4, table4_antagonist()));
  expect_round_trip(fitted(SpringLaw::kEq5, table4_antagonist()));
}

TEST(SpringModelTest, RoundTripHandMadeCubics) {
  expect_round_trip(spring_model_from_paper_units(SpringLaw::kEq4, -60.1, 170.1,
                                                  {0.911, 0.256, 7.00, 0.002, -0.201, 1.5}));
  expect_round_trip(spring_model_from_paper_units(SpringLaw::kEq5, -60.1, 170.1,
                                                  {3.0, 0.005, 0.01, 0.5, 10.0, 0.0}));
  // softening cubic (negative d^3 term): still the first crossing
  expect_round_trip(spring_model_from_paper_units(SpringLaw::kEq4, -60.1, 170.1,
                                                  {5.0, 0.2, 2.0, -1e-4, 0.0, 0.0}));
}

TEST(SpringModelTest, SlackAndNoPhysicalRoot) {
  // f <= 0: slack, d = 0
  for (double f : {0.0, -3.0}) {
    const DeformationEstimate e = invert_spring_model(table4_agonist(), 0.4e6, f);
    EXPECT_EQ(e.status, InversionStatus::kSlack);
    EXPECT_EQ(e.d_m, 0.0);
  }
  // antagonist at 0.1 MPa has A2 < 0: f peaks at d = A1 / (2|A2|); beyond it no root
  const std::array<double, 3> a = deformation_polynomial(table4_antagonist(), 0.1e6);
  ASSERT_LT(a[1], 0.0);
  const double f_max = a[0] * a[0] / (4 * -a[1]);
  const DeformationEstimate below = invert_spring_model(table4_antagonist(), 0.1e6, 0.999 * f_max);
  EXPECT_EQ(below.status, InversionStatus::kOk);
  EXPECT_LT(below.d_m, a[0] / (2 * -a[1]));
  const DeformationEstimate beyond = invert_spring_model(table4_antagonist(), 0.1e6, 1.001 * f_max);
  EXPECT_EQ(beyond.status, InversionStatus::kNoPhysicalRoot);
  EXPECT_EQ(beyond.d_m, 0.0);
}

TEST(SpringModelTest, LinearLimitWhenQuadraticTermVanishes) {
  // a3 p + a1 = 0 at p = 0.256 / 0.201 MPa: f = A1 d exactly
  const double p = 0.256 / 0.201 * 1e6;
  const SpringModel model = table4_agonist();
  const std::array<double, 3> a = deformation_polynomial(model, p);
  EXPECT_NEAR(a[1], 0.0, 1e-6 * std::abs(a[0]));
  const DeformationEstimate e = invert_spring_model(model, p, 50.0);
  ASSERT_EQ(e.status, InversionStatus::kOk);
  EXPECT_NEAR(spring_force(model, p, e.d_m), 50.0, 1e-9 * 50.0);
  // exactly zero quadratic term through the shared root finder
  EXPECT_DOUBLE_EQ(smallest_positive_root(0.0, 0.0, 4.0, 10.0), 2.5);
  EXPECT_LT(smallest_positive_root(0.0, 0.0, -4.0, 10.0), 0.0);
}

TEST(SpringModelTest, SmallestPositiveRootOfCubics) {
  // (x-1)(x-2)(x-3) = x^3 - 6x^2 + 11x - 6: roots 1, 2, 3
  EXPECT_NEAR(smallest_positive_root(1.0, -6.0, 11.0, 6.0), 1.0, 1e-14);
  // monotone cubic: the one real root solves it to round-off
  const double r = smallest_positive_root(2.0, 0.5, 3.0, 7.0);
  EXPECT_NEAR(2 * r * r * r + 0.5 * r * r + 3 * r, 7.0, 1e-12);
  // tiny leading coefficient: the quadratic roots are kept, the huge root is not chosen
  const double q = smallest_positive_root(1e-18, 1.0, 1.0, 2.0);  // x^2 + x - 2 -> 1
  EXPECT_NEAR(q, 1.0, 1e-12);
  // negative leading coefficient with no crossing
  EXPECT_LT(smallest_positive_root(-1.0, 0.0, -1.0, 1.0), 0.0);
}

TEST(SpringModelTest, NeverNaN) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const SpringModel eq5 = spring_model_from_paper_units(SpringLaw::kEq5, -60.1, 170.1,
                                                        {3.0, 0.005, 0.01, 0.5, 10.0, 0.0});
  for (const SpringModel& model : {table4_agonist(), table4_antagonist(), eq5}) {
    for (double p : {nan, inf, -inf, -1e6, 0.0, 0.4e6, 1e12}) {
      for (double f : {nan, inf, -inf, -1.0, 0.0, 1e-300, 54.67, 1e9, 1e300}) {
        const DeformationEstimate e = invert_spring_model(model, p, f);
        EXPECT_TRUE(std::isfinite(e.d_m)) << p << " " << f;
        if (e.status != InversionStatus::kOk) {
          EXPECT_EQ(e.d_m, 0.0);
        }
        if (!std::isfinite(p) || !std::isfinite(f)) {
          EXPECT_EQ(e.status, InversionStatus::kNoPhysicalRoot);
        }
      }
    }
  }
}

}  // namespace
}  // namespace pamsim
