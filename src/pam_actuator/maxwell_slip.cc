// maxwell_slip.cc: see maxwell_slip.h.
#include "pam_actuator/maxwell_slip.h"

#include <algorithm>
#include <cmath>

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {
namespace {

constexpr double kWeightSumTolerance = 1e-6;

}  // namespace

void validate_maxwell_slip(const MaxwellSlipParams& params, const std::string& prefix) {
  require_value(params.count >= 1 && params.count <= kMaxSlipElements, prefix + "breakaway_mm",
                "1 to 4 elements long", params.count);
  double sum = 0.0;
  for (int i = 0; i < params.count; ++i) {
    const std::string index = "[" + std::to_string(i) + "]";
    require_value(std::isfinite(params.breakaway_m[i]) && params.breakaway_m[i] > 0.0,
                  prefix + "breakaway_mm" + index, "> 0", params.breakaway_m[i] * 1e3);
    require_value(std::isfinite(params.weight[i]) && params.weight[i] > 0.0,
                  prefix + "weights" + index, "> 0", params.weight[i]);
    sum += params.weight[i];
  }
  require_value(std::fabs(sum - 1.0) <= kWeightSumTolerance, prefix + "weights", "summing to 1",
                sum);
}

void maxwell_slip_advance(const MaxwellSlipParams& params, double step_m, double* state) {
  // stick: the spring takes the whole step; slip: the block moves, the spring stays at +-1
  for (int i = 0; i < params.count; ++i) {
    state[i] = std::clamp(state[i] + step_m / params.breakaway_m[i], -1.0, 1.0);
  }
}

double maxwell_slip_force(const MaxwellSlipParams& params, const double* state, double up_n,
                          double down_n) {
  double f = 0.0;
  for (int i = 0; i < params.count; ++i) {
    f += params.weight[i] * state[i] * (state[i] >= 0.0 ? up_n : down_n);
  }
  return f;
}

}  // namespace pamsim
