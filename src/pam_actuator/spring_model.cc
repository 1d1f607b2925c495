// spring_model.cc: Eq. (1)-(5) of Yoshida and Hosoda, unit conversion, and the inversion
// f -> d, which is the embedded controller's (src/embedded/pamctl_spring.c).
#include "pam_actuator/spring_model.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

#include "base/enum_names.h"
#include "base/input_error.h"
#include "base/units.h"
#include "embedded/pamctl.h"

namespace pamsim {
namespace {

constexpr EnumName<SpringLaw> kLawNames[] = {
    {SpringLaw::kEq3, "eq3"}, {SpringLaw::kEq4, "eq4"}, {SpringLaw::kEq5, "eq5"}};
constexpr EnumName<InversionStatus> kStatusNames[] = {
    {InversionStatus::kOk, "ok"},
    {InversionStatus::kSlack, "slack"},
    {InversionStatus::kNoPhysicalRoot, "no_physical_root"}};

// exponents (i of p, j of d) of each term before the common factor d, paper order: the
// embedded controller's table
struct Term {
  int i;
  int j;
};

int32_t embedded_law(SpringLaw law) {
  switch (law) {
    case SpringLaw::kEq3:
      return PAMCTL_LAW_EQ3;
    case SpringLaw::kEq4:
      return PAMCTL_LAW_EQ4;
    case SpringLaw::kEq5:
      return PAMCTL_LAW_EQ5;
  }
  return PAMCTL_LAW_EQ3;
}

Term term(SpringLaw law, int k) {
  assert(k >= 0 && k < coefficient_count(law));
  std::int32_t i = 0, j = 0;
  pamctl_law_term(embedded_law(law), k, &i, &j);
  return {i, j};
}

// SI coefficient per paper coefficient: (1e-6 MPa/Pa)^i (1e3 mm/m)^(j+1)
double paper_to_si_factor(const Term& t) {
  return std::pow(1.0 / units::kPaPerMPa, t.i) * std::pow(1.0 / units::kMPerMm, t.j + 1);
}

}  // namespace

const char* to_string(SpringLaw law) { return name_of(kLawNames, law); }

SpringLaw parse_spring_law(const std::string& name, const std::string& context) {
  return parse_name(kLawNames, name, context);
}

int coefficient_count(SpringLaw law) { return pamctl_law_term_count(embedded_law(law)); }

std::string coefficient_name(SpringLaw law, int k) {
  assert(k >= 0 && k < coefficient_count(law));
  const char letter = law == SpringLaw::kEq3 ? 'a' : law == SpringLaw::kEq4 ? 'b' : 'c';
  return std::string(1, letter) + std::to_string(k);
}

int pressure_exponent(SpringLaw law, int k) { return term(law, k).i; }
int deformation_exponent(SpringLaw law, int k) { return term(law, k).j; }

SpringModel spring_model_from_paper_units(SpringLaw law, double m_mm_per_mpa, double h_mm,
                                          const std::array<double, 6>& coef_paper) {
  SpringModel model;
  model.law = law;
  // Eq. (2): mm/MPa -> m/Pa, mm -> m
  model.m_m_per_pa = m_mm_per_mpa * units::kMPerMm / units::kPaPerMPa;
  model.h_m = units::mm_to_m(h_mm);
  for (int k = 0; k < coefficient_count(law); ++k) {
    model.coef[k] = coef_paper[k] * paper_to_si_factor(term(law, k));
  }
  return model;
}

void spring_model_to_paper_units(const SpringModel& model, double* m_mm_per_mpa, double* h_mm,
                                 std::array<double, 6>* coef_paper) {
  *m_mm_per_mpa = model.m_m_per_pa * units::kPaPerMPa / units::kMPerMm;
  *h_mm = units::m_to_mm(model.h_m);
  coef_paper->fill(0.0);
  for (int k = 0; k < coefficient_count(model.law); ++k) {
    (*coef_paper)[k] = model.coef[k] / paper_to_si_factor(term(model.law, k));
  }
}

double natural_length(const SpringModel& model, double p_pa) {
  return model.m_m_per_pa * p_pa + model.h_m;  // Eq. (2)
}

std::array<double, 3> deformation_polynomial(const SpringModel& model, double p_pa) {
  // collect c_k p^i into the coefficient of d^(j+1): the embedded controller's code
  const pamctl_spring spring = embedded_spring(model);
  std::array<double, 3> a{};
  pamctl_spring_polynomial(&spring, p_pa, a.data());
  return a;
}

pamctl_spring embedded_spring(const SpringModel& model) {
  pamctl_spring spring{};
  spring.law = embedded_law(model.law);
  spring.m_m_per_pa = model.m_m_per_pa;
  spring.h_m = model.h_m;
  for (std::size_t k = 0; k < model.coef.size(); ++k) spring.coef[k] = model.coef[k];
  return spring;
}

double spring_force(const SpringModel& model, double p_pa, double d_m) {
  // slack line pulls nothing
  if (!(d_m > 0.0)) return 0.0;
  // Eq. (3)-(5) as A1 d + A2 d^2 + A3 d^3
  const std::array<double, 3> a = deformation_polynomial(model, p_pa);
  return ((a[2] * d_m + a[1]) * d_m + a[0]) * d_m;
}

double spring_stiffness(const SpringModel& model, double p_pa, double d_m) {
  if (!(d_m > 0.0)) return 0.0;
  const std::array<double, 3> a = deformation_polynomial(model, p_pa);
  return (3.0 * a[2] * d_m + 2.0 * a[1]) * d_m + a[0];
}

const char* to_string(InversionStatus status) { return name_of(kStatusNames, status); }

double smallest_positive_root(double a3, double a2, double a1, double f) {
  return pamctl_smallest_positive_root(a3, a2, a1, f);
}

DeformationEstimate invert_spring_model(const SpringModel& model, double p_pa, double f_n) {
  // Eq. (10): the embedded controller's inversion (src/embedded/pamctl_spring.c)
  const pamctl_spring spring = embedded_spring(model);
  DeformationEstimate out;
  const pamctl_inversion status = pamctl_invert_spring(&spring, p_pa, f_n, &out.d_m);
  out.status = inversion_status(status);
  return out;
}

InversionStatus inversion_status(pamctl_inversion status) {
  switch (status) {
    case PAMCTL_INVERSION_OK:
      return InversionStatus::kOk;
    case PAMCTL_INVERSION_SLACK:
      return InversionStatus::kSlack;
    case PAMCTL_INVERSION_NO_ROOT:
      break;
  }
  return InversionStatus::kNoPhysicalRoot;
}

}  // namespace pamsim
