// spring_model.cc: Eq. (1)-(5) of seeds/000, unit conversion and the inversion f -> d.
#include "pam_actuator/spring_model.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "base/enum_names.h"
#include "base/input_error.h"
#include "base/units.h"

namespace pamsim {
namespace {

constexpr EnumName<SpringLaw> kLawNames[] = {
    {SpringLaw::kEq3, "eq3"}, {SpringLaw::kEq4, "eq4"}, {SpringLaw::kEq5, "eq5"}};
constexpr EnumName<InversionStatus> kStatusNames[] = {
    {InversionStatus::kOk, "ok"},
    {InversionStatus::kSlack, "slack"},
    {InversionStatus::kNoPhysicalRoot, "no_physical_root"}};

// exponents (i of p, j of d) of each term before the common factor d, paper order
struct Term {
  int i;
  int j;
};
constexpr Term kEq3Terms[] = {{0, 0}, {0, 1}, {1, 0}, {1, 1}};                   // a0..a3
constexpr Term kEq4Terms[] = {{0, 0}, {0, 1}, {1, 0}, {0, 2}, {1, 1}, {2, 0}};   // b0..b5
constexpr Term kEq5Terms[] = {{0, 0}, {0, 2}, {1, 2}, {2, 1}, {3, 0}};           // c0..c4

Term term(SpringLaw law, int k) {
  assert(k >= 0 && k < coefficient_count(law));
  switch (law) {
    case SpringLaw::kEq3: return kEq3Terms[k];
    case SpringLaw::kEq4: return kEq4Terms[k];
    case SpringLaw::kEq5: return kEq5Terms[k];
  }
  return {0, 0};
}

// SI coefficient per paper coefficient: (1e-6 MPa/Pa)^i (1e3 mm/m)^(j+1)
double paper_to_si_factor(const Term& t) {
  return std::pow(1.0 / units::kPaPerMPa, t.i) * std::pow(1.0 / units::kMPerMm, t.j + 1);
}

// Eq. (3) and the quadratic case: smallest positive root of a2 x^2 + a1 x - f = 0, f > 0,
// by the numerically stable form q = -(a1 + sgn(a1) sqrt(disc)) / 2, roots q/a2 and -f/q.
double smallest_positive_quadratic_root(double a2, double a1, double f) {
  // linear limit
  if (a2 == 0.0) return a1 > 0.0 ? f / a1 : -1.0;
  const double disc = a1 * a1 + 4.0 * a2 * f;
  if (!(disc >= 0.0)) return -1.0;

  // both roots without cancellation; keep the smallest positive finite one
  const double q = -0.5 * (a1 + std::copysign(std::sqrt(disc), a1));
  if (q == 0.0) return -1.0;
  const double r1 = q / a2;
  const double r2 = -f / q;
  double best = -1.0;
  for (double r : {r1, r2}) {
    if (r > 0.0 && std::isfinite(r) && (best < 0.0 || r < best)) best = r;
  }
  return best;
}

// g(x) = a3 x^3 + a2 x^2 + a1 x - f, in Horner form
struct Cubic {
  double a3, a2, a1, f;
  double value(double x) const { return ((a3 * x + a2) * x + a1) * x - f; }
  double slope(double x) const { return (3.0 * a3 * x + 2.0 * a2) * x + a1; }
};

// root of g in [lo, hi] where g(lo) < 0 <= g(hi) and g is monotone: Newton steps kept
// inside the bracket, bisection when a step leaves it; converges to a few ulps
double bracketed_newton(const Cubic& g, double lo, double hi, double x) {
  for (int it = 0; it < 100; ++it) {
    const double gx = g.value(x);
    if (gx == 0.0) return x;
    if (gx < 0.0) lo = x; else hi = x;
    const double dg = g.slope(x);
    double next = x - gx / dg;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - x) <= 4.0 * std::numeric_limits<double>::epsilon() * std::abs(next)) {
      return next;
    }
    x = next;
  }
  return x;
}

// first upper end where g >= 0 beyond `from`, by doubling a scale guess; -1 if none found
double bracket_above(const Cubic& g, double from) {
  double step = std::max(from, 0.0);
  if (step == 0.0) {
    // scale guess from the dominant terms alone: f/|a1|, sqrt(f/|a2|), cbrt(f/|a3|)
    step = std::numeric_limits<double>::max();
    if (g.a1 != 0.0) step = std::min(step, g.f / std::abs(g.a1));
    if (g.a2 != 0.0) step = std::min(step, std::sqrt(g.f / std::abs(g.a2)));
    if (g.a3 != 0.0) step = std::min(step, std::cbrt(g.f / std::abs(g.a3)));
  }
  double hi = from + step;
  for (int it = 0; it < 2100 && std::isfinite(hi); ++it) {
    if (g.value(hi) >= 0.0) return hi;
    hi = from + 2.0 * (hi - from);
  }
  return -1.0;
}

// start for Newton inside (lo, hi): the root without the cubic term when it falls there
// (close whenever a3 x^3 is small), else the middle
double initial_guess(const Cubic& g, double lo, double hi) {
  const double x = smallest_positive_quadratic_root(g.a2, g.a1, g.f);
  return x > lo && x < hi ? x : 0.5 * (lo + hi);
}

// cubic case: g(0) = -f < 0; g is monotone between its positive critical points
// 0 = t0 < t1 < t2, so the first piece whose right end has g >= 0 holds the smallest
// positive root; the last piece is unbounded and is bracketed by doubling
double smallest_positive_cubic_root(double a3, double a2, double a1, double f) {
  const Cubic g{a3, a2, a1, f};

  // positive critical points: roots of g'(x) = 3 a3 x^2 + 2 a2 x + a1
  double crit[2];
  int n_crit = 0;
  const double qa = 3.0 * a3, qb = 2.0 * a2, disc = qb * qb - 4.0 * qa * a1;
  if (disc > 0.0) {
    const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
    for (double r : {q / qa, q != 0.0 ? a1 / q : -1.0}) {
      if (r > 0.0 && std::isfinite(r)) crit[n_crit++] = r;
    }
    if (n_crit == 2 && crit[0] > crit[1]) std::swap(crit[0], crit[1]);
  }

  // walk the monotone pieces
  double lo = 0.0;
  for (int k = 0; k < n_crit; ++k) {
    const double gk = g.value(crit[k]);
    if (gk == 0.0) return crit[k];
    if (gk > 0.0) return bracketed_newton(g, lo, crit[k], initial_guess(g, lo, crit[k]));
    lo = crit[k];
  }

  // last piece: a root only if g grows without bound
  if (!(a3 > 0.0)) return -1.0;
  const double hi = bracket_above(g, lo);
  if (hi < 0.0) return -1.0;
  return bracketed_newton(g, lo, hi, initial_guess(g, lo, hi));
}

}  // namespace

const char* to_string(SpringLaw law) { return name_of(kLawNames, law); }

SpringLaw parse_spring_law(const std::string& name, const std::string& context) {
  return parse_name(kLawNames, name, context);
}

int coefficient_count(SpringLaw law) {
  switch (law) {
    case SpringLaw::kEq3: return 4;
    case SpringLaw::kEq4: return 6;
    case SpringLaw::kEq5: return 5;
  }
  return 0;
}

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
  // collect c_k p^i into the coefficient of d^(j+1)
  std::array<double, 3> a{};
  const double p_pow[4] = {1.0, p_pa, p_pa * p_pa, p_pa * p_pa * p_pa};
  for (int k = 0; k < coefficient_count(model.law); ++k) {
    const Term t = term(model.law, k);
    a[t.j] += model.coef[k] * p_pow[t.i];
  }
  return a;
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
  if (!(f > 0.0) || !std::isfinite(f) || !std::isfinite(a1) || !std::isfinite(a2) ||
      !std::isfinite(a3)) {
    return -1.0;
  }
  if (a3 == 0.0) return smallest_positive_quadratic_root(a2, a1, f);
  return smallest_positive_cubic_root(a3, a2, a1, f);
}

DeformationEstimate invert_spring_model(const SpringModel& model, double p_pa, double f_n) {
  DeformationEstimate out;
  // non-finite input: nothing physical to report
  if (!std::isfinite(p_pa) || !std::isfinite(f_n)) {
    out.status = InversionStatus::kNoPhysicalRoot;
    return out;
  }
  // a slack line reads no force (Fig. 7 of seeds/000): d = 0
  if (f_n <= 0.0) {
    out.status = InversionStatus::kSlack;
    return out;
  }
  // Eq. (3) is quadratic in d (A3 = 0): closed form; Eq. (4), (5) are cubic
  const std::array<double, 3> a = deformation_polynomial(model, p_pa);
  const double d = smallest_positive_root(a[2], a[1], a[0], f_n);
  if (d > 0.0 && std::isfinite(d)) {
    out.d_m = d;
    out.status = InversionStatus::kOk;
  } else {
    out.status = InversionStatus::kNoPhysicalRoot;
  }
  return out;
}

}  // namespace pamsim
