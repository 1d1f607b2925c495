// maxwell_slip.cc: see maxwell_slip.h.
#include "pam_actuator/maxwell_slip.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include "base/format.h"
#include "base/input_error.h"

namespace pamsim {
namespace {

double slip_force(const MaxwellSlipElement& e, double p_pa) {
  return e.slip_force_n + e.slip_force_per_pa_n * std::max(p_pa, 0.0);
}

void require(bool ok, const std::string& key, const char* allowed, double value) {
  if (!ok) throw InputError(key + " must be " + allowed + ", got " + format_value(value));
}

}  // namespace

void validate_maxwell_slip(const std::vector<MaxwellSlipElement>& elements,
                           const std::string& prefix) {
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const MaxwellSlipElement& e = elements[i];
    const std::string key = prefix + "elements[" + std::to_string(i) + "].";
    require(std::isfinite(e.stiffness_n_per_m) && e.stiffness_n_per_m > 0.0,
            key + "stiffness_N_per_mm", "> 0", e.stiffness_n_per_m * 1e-3);
    require(std::isfinite(e.slip_force_n) && e.slip_force_n >= 0.0, key + "slip_force_N",
            ">= 0", e.slip_force_n);
    require(std::isfinite(e.slip_force_per_pa_n) && e.slip_force_per_pa_n >= 0.0,
            key + "slip_force_N_per_MPa", ">= 0", e.slip_force_per_pa_n * 1e6);
  }
}

MaxwellSlip::MaxwellSlip(std::vector<MaxwellSlipElement> elements)
    : elements_(std::move(elements)), deflection_m_(elements_.size(), 0.0) {
  assert(std::all_of(elements_.begin(), elements_.end(),
                     [](const MaxwellSlipElement& e) { return e.stiffness_n_per_m > 0.0; }));
}

double MaxwellSlip::update(double position_m, double p_pa) {
  const double step = started_ ? position_m - position_m_ : 0.0;
  started_ = true;
  position_m_ = position_m;
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    // stick: the spring takes the whole step; slip: the block moves, the spring holds F_i
    const double limit = slip_force(elements_[i], p_pa) / elements_[i].stiffness_n_per_m;
    deflection_m_[i] = std::clamp(deflection_m_[i] + step, -limit, limit);
  }
  return force_n();
}

double MaxwellSlip::force_n() const {
  double f = 0.0;
  for (std::size_t i = 0; i < elements_.size(); ++i) {
    f += elements_[i].stiffness_n_per_m * deflection_m_[i];
  }
  return f;
}

double MaxwellSlip::max_force_n(double p_pa) const {
  double f = 0.0;
  for (const MaxwellSlipElement& e : elements_) f += slip_force(e, p_pa);
  return f;
}

}  // namespace pamsim
