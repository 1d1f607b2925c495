// prony_creep.cc: see prony_creep.h.
#include "sensing/prony_creep.h"

#include <cassert>
#include <cmath>
#include <utility>

#include "sensing/checks.h"

namespace pamsim {

void prony_lists(const std::vector<PronyTerm>& terms, std::vector<double>* weights,
                 std::vector<double>* times) {
  for (const PronyTerm& t : terms) {
    weights->push_back(t.weight);
    times->push_back(t.time_s);
  }
}

void validate_prony(const std::vector<PronyTerm>& terms, const std::string& weights_key,
                    const std::string& times_key) {
  for (std::size_t i = 0; i < terms.size(); ++i) {
    const std::string index = "[" + std::to_string(i) + "]";
    checks::require_non_negative(weights_key + index, terms[i].weight);
    checks::require_positive(times_key + index, terms[i].time_s);
  }
}

PronyCreep::PronyCreep(std::vector<PronyTerm> terms, double step_s)
    : terms_(std::move(terms)), state_(terms_.size(), 0.0) {
  assert(step_s > 0.0);
  decay_.reserve(terms_.size());
  for (const PronyTerm& t : terms_) {
    assert(t.time_s > 0.0 && t.weight >= 0.0);
    decay_.push_back(std::exp(-step_s / t.time_s));
  }
}

double PronyCreep::step(double elastic) {
  double out = elastic;
  for (std::size_t i = 0; i < terms_.size(); ++i) {
    state_[i] = elastic + (state_[i] - elastic) * decay_[i];
    out += terms_[i].weight * state_[i];
  }
  return out;
}

double PronyCreep::long_term_factor() const {
  double factor = 1.0;
  for (const PronyTerm& t : terms_) factor += t.weight;
  return factor;
}

}  // namespace pamsim
