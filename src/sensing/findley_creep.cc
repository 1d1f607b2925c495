// findley_creep.cc: see findley_creep.h.
#include "sensing/findley_creep.h"

#include <cassert>
#include <cmath>

namespace pamsim {
namespace {

constexpr int kFirstDecade = -2;  // tau = 0.01 s
constexpr int kLastDecade = 9;    // tau = 1e9 s

}  // namespace

double findley_creep(const FindleyCreep& law, double t_s) {
  return law.creep_1000h * std::pow(t_s / kFindleyReferenceS, law.exponent);
}

std::vector<PronyTerm> findley_prony_terms(const FindleyCreep& law) {
  const double n = law.exponent;
  assert(n > 0.0 && n <= kMaxFindleyExponent && law.creep_1000h >= 0.0);
  std::vector<PronyTerm> terms;
  if (law.creep_1000h == 0.0) return terms;
  const double a = law.creep_1000h / std::pow(kFindleyReferenceS, n);  // c(t) = a t^n
  const double gamma = std::tgamma(1.0 - n);
  for (int k = kFirstDecade; k <= kLastDecade; ++k) {
    const double tau = std::pow(10.0, k);
    const double weight = k == kFirstDecade ? a * std::pow(tau * std::sqrt(10.0), n) / gamma
                                            : a * n * std::pow(tau, n) / gamma * std::log(10.0);
    terms.push_back({weight, tau});
  }
  return terms;
}

}  // namespace pamsim
