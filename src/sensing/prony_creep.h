// prony_creep.h: linear viscoelastic creep and recovery as a Prony series of Kelvin-Voigt
// elements, the multi-exponential form in which creep of polymers is tabulated and load
// cells are tested (OIML R60: creep under constant load, then its recovery). The creep
// compliance is J(t) = J0 (1 + sum g_i (1 - exp(-t / tau_i))); driven by the elastic
// response x(t) = J0 sigma(t), the element states obey dq_i/dt = (x - q_i) / tau_i and the
// output is x + sum g_i q_i. With x held over each step (the control tick), the update
// q_i <- x + (q_i - x) exp(-dt / tau_i) is exact, so a load step gives the closed form at
// every tick. Used for the PMMA board under the gauge and the fiber sensor's drift (the
// fishing line's creep is one such element, kept by the force callback,
// sim/core/pam_callback.h); the weights and times are each material's, cited where given.
#pragma once

#include <string>
#include <vector>

namespace pamsim {

struct PronyTerm {
  double weight = 0.0;  // g_i >= 0: the element's share of the long-term compliance
  double time_s = 0.0;  // tau_i > 0: its retardation time
};

// Throws InputError "<weights_key>[i] must be ..., got <value>" for a negative or non-finite
// weight, "<times_key>[i] ..." for a non-positive or non-finite time (the two lists a file
// gives them in).
void validate_prony(const std::vector<PronyTerm>& terms, const std::string& weights_key,
                    const std::string& times_key);

// The series as the two lists a file gives it in: its weights and its times.
void prony_lists(const std::vector<PronyTerm>& terms, std::vector<double>* weights,
                 std::vector<double>* times);

class PronyCreep {
 public:
  // Terms must have passed validate_prony (asserted). Starts unloaded (all q_i = 0).
  PronyCreep(std::vector<PronyTerm> terms, double step_s);

  // The response at the end of a step over which the elastic response was `elastic`.
  double step(double elastic);
  // The long-term factor 1 + sum g_i: a load held for ever reads this much more.
  double long_term_factor() const;

 private:
  std::vector<PronyTerm> terms_;
  std::vector<double> decay_;  // exp(-dt / tau_i)
  std::vector<double> state_;  // q_i
};

}  // namespace pamsim
