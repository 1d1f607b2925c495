// avbdl_friction.cc: the fibre friction term of the AVBDL plant (pamsim's addition to
// Pipan et al.'s law), see avbdl.h: its magnitude, the rate-independent force, the smooth one
// avbdl_force adds to Eq. (25), and the Maxwell-slip one.
#include <algorithm>
#include <cmath>

#include "pam_actuator/avbdl.h"

namespace pamsim {

double avbdl_friction_magnitude(const AvbdlParams& p, double p_pa, double length_m,
                                StretchDirection direction) {
  const AvbdlFrictionCoefficients& c =
      direction == StretchDirection::kExtension ? p.friction.extension : p.friction.contraction;
  // F_f = F0 + p (A0 + A1 eps): normal load from pressure on a strain-dependent contact
  const double strain = (p.length_m - length_m) / p.length_m;
  const double area = std::max(c.pressure_area_m2 + c.strain_area_m2 * strain, 0.0);
  return c.force_n + std::max(p_pa, 0.0) * area;
}

double avbdl_friction_force(const AvbdlParams& p, double p_pa, double length_m,
                            StretchDirection direction) {
  const double f = avbdl_friction_magnitude(p, p_pa, length_m, direction);
  return direction == StretchDirection::kExtension ? f : -f;
}

double avbdl_smooth_friction_force(const AvbdlParams& p, double p_pa, double length_m,
                                   double length_rate_m_per_s) {
  const StretchDirection direction =
      length_rate_m_per_s > 0.0 ? StretchDirection::kExtension : StretchDirection::kContraction;
  return std::tanh(length_rate_m_per_s / p.friction.velocity_scale_m_per_s) *
         avbdl_friction_magnitude(p, p_pa, length_m, direction);
}

double avbdl_slip_friction_force(const AvbdlParams& p, double p_pa, double length_m,
                                 const double* slip_state) {
  const double up = avbdl_friction_magnitude(p, p_pa, length_m, StretchDirection::kExtension);
  const double down = avbdl_friction_magnitude(p, p_pa, length_m, StretchDirection::kContraction);
  return maxwell_slip_force(p.friction.slip, slip_state, up, down);
}

double avbdl_friction(const AvbdlParams& p, double p_pa, double length_m,
                      const FrictionInput& input) {
  if (p.friction.model == FrictionModel::kSmooth) {
    return avbdl_smooth_friction_force(p, p_pa, length_m, input.length_rate_m_per_s);
  }
  if (input.slip_state == nullptr) return 0.0;  // unloaded elements hold nothing
  return avbdl_slip_friction_force(p, p_pa, length_m, input.slip_state);
}

}  // namespace pamsim
