// spring_model.h: the nonlinear spring model of a PAM from Yoshida and Hosoda,
// Eq. (1)-(5): natural length, the three force laws, their stiffness, and
// the inversion from measured (p, f) to deformation d used for length estimation.
//
// Every law has the form f = d * sum_k c_k p^i_k d^j_k, i.e. a polynomial in d:
//   f(p, d) = A1(p) d + A2(p) d^2 + A3(p) d^3
// Eq. (3): f = (a3 p d + a2 p + a1 d + a0) d
// Eq. (4): f = (b5 p^2 + b4 p d + b3 d^2 + b2 p + b1 d + b0) d
// Eq. (5): f = (c4 p^3 + c3 p^2 d + c2 p d^2 + c1 d^2 + c0) d
// Coefficients are stored in SI (p in Pa gauge, d in m, f in N); the paper's units
// (p in MPa, d in mm, f in N) are converted once by spring_model_from_paper_units.
#pragma once

#include <array>
#include <string>

#include "embedded/pamctl.h"

namespace pamsim {

enum class SpringLaw { kEq3, kEq4, kEq5 };

// "eq3", "eq4", "eq5"
const char* to_string(SpringLaw law);
// Throws InputError on anything else, naming `context` (e.g. "params.toml: model.law").
SpringLaw parse_spring_law(const std::string& name, const std::string& context);

// Number of coefficients: 4 (a0..a3), 6 (b0..b5), 5 (c0..c4).
int coefficient_count(SpringLaw law);
// Name of coefficient k in the paper's notation: "a0", "b3", "c4", ...
std::string coefficient_name(SpringLaw law, int k);
// Exponents of p and d in the k-th term (before the common factor d).
int pressure_exponent(SpringLaw law, int k);
int deformation_exponent(SpringLaw law, int k);

struct SpringModel {
  SpringLaw law = SpringLaw::kEq3;
  double m_m_per_pa = 0.0;       // Eq. (2) slope [m/Pa]
  double h_m = 0.0;              // Eq. (2) intercept [m]
  std::array<double, 6> coef{};  // SI coefficients, paper order, unused entries 0
};

// Paper units: m [mm/MPa], h [mm], coefficients giving f [N] from p [MPa], d [mm].
// `coef_paper` holds coefficient_count(law) values in paper order.
SpringModel spring_model_from_paper_units(SpringLaw law, double m_mm_per_mpa, double h_mm,
                                          const std::array<double, 6>& coef_paper);
// The inverse conversion (for writing parameter files and JSON).
void spring_model_to_paper_units(const SpringModel& model, double* m_mm_per_mpa, double* h_mm,
                                 std::array<double, 6>* coef_paper);

// Eq. (2): natural length l_n = m p + h [m], p gauge [Pa].
double natural_length(const SpringModel& model, double p_pa);

// The model as the embedded controller holds it (src/embedded/pamctl.h), the same SI values.
pamctl_spring embedded_spring(const SpringModel& model);

// Polynomial coefficients in d at pressure p: f = A[0] d + A[1] d^2 + A[2] d^3.
std::array<double, 3> deformation_polynomial(const SpringModel& model, double p_pa);

// Eq. (3)-(5): force [N] at gauge pressure p [Pa] and deformation d [m].
// d <= 0 is a slack line: zero force.
double spring_force(const SpringModel& model, double p_pa, double d_m);

// df/dd [N/m]; zero for d <= 0.
double spring_stiffness(const SpringModel& model, double p_pa, double d_m);

enum class InversionStatus {
  kOk,              // d > 0 solves f(p, d) = f
  kSlack,           // f <= 0: the line is slack, d = 0 (the paper's Fig. 7 behaviour)
  kNoPhysicalRoot,  // no non-negative root: f is beyond what the law can produce at p
};
const char* to_string(InversionStatus status);

// The embedded controller's inversion status as pamsim names it.
InversionStatus inversion_status(pamctl_inversion status);

struct DeformationEstimate {
  double d_m = 0.0;  // always finite; 0 unless status == kOk
  InversionStatus status = InversionStatus::kSlack;
};

// Length estimation by inversion (Eq. (3) solved for d, Eq. (10) with f = dV/q):
// the smallest positive root of A3 d^3 + A2 d^2 + A1 d - f = 0. Closed form for Eq. (3)
// (with its linear limit when A2 vanishes); a robust cubic for Eq. (4) and (5).
// Never returns NaN; a non-finite input gives kNoPhysicalRoot.
DeformationEstimate invert_spring_model(const SpringModel& model, double p_pa, double f_n);

// Smallest positive real root of a3 x^3 + a2 x^2 + a1 x - f = 0 (f > 0), or a negative
// value when there is none. Shared by the spring model and the Wickramatunge model.
double smallest_positive_root(double a3, double a2, double a1, double f);

}  // namespace pamsim
