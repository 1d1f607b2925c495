// bladder_relaxation.h: the bladder rubber's viscoelasticity, as a rate term on the AVBDL
// bladder force. The hyperelastic laws of avbdl.h are fitted to Treloar's quasi-static data,
// so they give the rubber's relaxed (long-term) response; a rubber deformed quickly pulls
// more, and the extra relaxes.
// Fung's quasi-linear viscoelasticity (Y. C. Fung, Biomechanics, Springer 1981, Ch. 7) puts
// that on the elastic response: the bladder's contribution to the pull is
//   F_b(t) = F_e(L(t)) + sum_i h_i(t),   dh_i/dt = g_i dF_e/dt - h_i / tau_i,
// a generalized Maxwell (Prony) series with relaxation G(t) = 1 + sum g_i exp(-t / tau_i)
// relative to the relaxed response F_e = dW/dL (Pipan et al., Eq. (23)-(25)). A step of F_e
// is answered by (1 + sum g_i) of it at once, relaxing to 1.
#pragma once

#include <array>
#include <string>

namespace pamsim {

inline constexpr int kMaxRelaxationTerms = 4;

// A material with a loss tangent tan(delta) nearly constant over a band of frequencies (a
// rubber far above its glass transition) has a log-uniform relaxation spectrum of height
// h = 2 tan(delta) / pi; one term per decade of tau across the band stands in for it with
// g_i = h ln(10) (Tschoegl, The Phenomenological Theory of Linear Viscoelastic Behavior,
// Springer 1989, Ch. 4: G'' = (pi / 2) H for a slowly varying spectrum). The shipped plant
// files do not use it (docs/physics.md, departures: no checked source for the tube's loss
// tangent, and with 0.05 it moves the drop by at most 0.1 deg, the bladder carrying about 4 %
// of the muscle's stiffness). It acts in the co-simulation (sim/core/pam_callback.h keeps
// its state per trial); the tensile test's points are read at rest, relaxed.
struct BladderRelaxation {
  int count = 0;                                     // 0: elastic (no rate term)
  std::array<double, kMaxRelaxationTerms> weight{};  // g_i >= 0
  std::array<double, kMaxRelaxationTerms> time_s{};  // tau_i > 0 [s]
};

// Throws InputError "<prefix><key> must be ..., got <value>" (keys in the plant file's
// names: "relaxation_weights[i]", "relaxation_times_s[i]", "relaxation_times_s" for the
// count) for a count outside 0..kMaxRelaxationTerms, a negative or non-finite weight, or a
// non-positive or non-finite time.
void validate_bladder_relaxation(const BladderRelaxation& params, const std::string& prefix);

// Update over a step dt with F_e linear in time (the exact solution of the ODE above for a
// ramp; the recursion of Taylor, Pister & Goudreau, Int. J. Numer. Methods Eng. 2, 45 (1970),
// as finite-element codes use it):
//   h_i <- e_i h_i + g_i (1 - e_i) tau_i / dt  dF_e,      e_i = exp(-dt / tau_i).
// exp(-dt / tau_i) for each term, and (1 - e_i) tau_i / dt: the step's constants.
struct RelaxationStep {
  std::array<double, kMaxRelaxationTerms> decay{};
  std::array<double, kMaxRelaxationTerms> ramp_gain{};
};
RelaxationStep relaxation_step(const BladderRelaxation& params, double step_s);

// The overstresses `state` (params.count values [N]) after a step over which the relaxed
// force changed by elastic_change_n, written into `next`; returns their sum [N]. `state`
// and `next` may be the same array.
double relaxation_advance(const BladderRelaxation& params, const RelaxationStep& step,
                          const double* state, double elastic_change_n, double* next);

// Closed forms (tested): a ramp of rate r gives h_i = g_i r tau_i (1 - exp(-t / tau_i)); a
// sinusoid F_e = A sin(w t) is answered with the loss modulus
//   G''(w) = sum g_i w tau_i / (1 + w^2 tau_i^2),
// storage G'(w) = 1 + sum g_i w^2 tau_i^2 / (1 + w^2 tau_i^2), and dissipates
// pi A^2 G''(w) / k per cycle in a spring of relaxed stiffness k.
// G''(w) and G'(w) of the series at angular frequency w [rad/s].
double relaxation_loss_modulus(const BladderRelaxation& params, double omega_rad_s);
double relaxation_storage_modulus(const BladderRelaxation& params, double omega_rad_s);

}  // namespace pamsim
