// bladder_relaxation.cc: see bladder_relaxation.h.
#include "pam_actuator/bladder_relaxation.h"

#include <cassert>
#include <cmath>

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {

void validate_bladder_relaxation(const BladderRelaxation& params, const std::string& prefix) {
  require_value(params.count >= 0 && params.count <= kMaxRelaxationTerms,
                prefix + "relaxation_times_s", "0 to 4 terms long", params.count);
  for (int i = 0; i < params.count; ++i) {
    const std::string index = "[" + std::to_string(i) + "]";
    require_value(std::isfinite(params.weight[i]) && params.weight[i] >= 0.0,
                  prefix + "relaxation_weights" + index, ">= 0", params.weight[i]);
    require_value(std::isfinite(params.time_s[i]) && params.time_s[i] > 0.0,
                  prefix + "relaxation_times_s" + index, "> 0 s", params.time_s[i]);
  }
}

RelaxationStep relaxation_step(const BladderRelaxation& params, double step_s) {
  assert(step_s > 0.0);
  RelaxationStep step;
  for (int i = 0; i < params.count; ++i) {
    const double x = step_s / params.time_s[i];
    step.decay[i] = std::exp(-x);
    step.ramp_gain[i] = -std::expm1(-x) / x;  // (1 - e) tau / dt, accurate for small x
  }
  return step;
}

double relaxation_advance(const BladderRelaxation& params, const RelaxationStep& step,
                          const double* state, double elastic_change_n, double* next) {
  double sum = 0.0;
  for (int i = 0; i < params.count; ++i) {
    next[i] = step.decay[i] * state[i] + params.weight[i] * step.ramp_gain[i] * elastic_change_n;
    sum += next[i];
  }
  return sum;
}

double relaxation_loss_modulus(const BladderRelaxation& params, double omega_rad_s) {
  double loss = 0.0;
  for (int i = 0; i < params.count; ++i) {
    const double wt = omega_rad_s * params.time_s[i];
    loss += params.weight[i] * wt / (1.0 + wt * wt);
  }
  return loss;
}

double relaxation_storage_modulus(const BladderRelaxation& params, double omega_rad_s) {
  double storage = 1.0;
  for (int i = 0; i < params.count; ++i) {
    const double wt = omega_rad_s * params.time_s[i];
    storage += params.weight[i] * wt * wt / (1.0 + wt * wt);
  }
  return storage;
}

}  // namespace pamsim
