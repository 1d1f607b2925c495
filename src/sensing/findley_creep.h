// findley_creep.h: a polymer's creep as Findley's power law, c(t) = A (t / 1000 h)^n, the
// creep strain per unit elastic strain after a load held t (Findley, W. N. (1944), "Creep
// characteristics of plastics", ASTM Symposium on Plastics, 118-134; for cast PMMA n = 0.24
// in flexure at 8-55 C and 5-25 MPa over 450 h, and a creep increment of about 60 % at
// 1000 h, the figures the board's keys default to and bracket).
//
// A power law has no finite state, so the gauge runs it as a Prony series (prony_creep.h)
// whose terms sample its retardation spectrum, one per decade of time from 0.01 s to 1e9 s:
// for c(t) = a t^n,  c(t) = integral of L(tau) (1 - exp(-t / tau)) d(ln tau)  with
//   L(tau) = a n tau^n / Gamma(1 - n),
// so a term at tau_k weighs L(tau_k) ln 10, and the first also carries the spectrum below it,
// a (tau_0 sqrt(10))^n / Gamma(1 - n). For n <= 0.7 the series' step response is within 2 %
// of the law from 0.1 s to 1e4 s (tests/sensing/findley_creep_test.cc); polymers' exponents
// lie near 0.1-0.4.
#pragma once

#include <vector>

#include "sensing/prony_creep.h"

namespace pamsim {

struct FindleyCreep {
  double exponent = 0.24;    // n, in (0, kMaxFindleyExponent]
  double creep_1000h = 0.0;  // A >= 0: the creep after 1000 h per unit elastic strain
};
inline constexpr double kMaxFindleyExponent = 0.7;
inline constexpr double kFindleyReferenceS = 1000.0 * 3600.0;

// The law's creep c(t) at t >= 0 [s].
double findley_creep(const FindleyCreep& law, double t_s);

// The Prony series of the law (none when creep_1000h is 0). The law must hold its ranges.
std::vector<PronyTerm> findley_prony_terms(const FindleyCreep& law);

}  // namespace pamsim
