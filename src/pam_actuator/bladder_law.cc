// bladder_law.cc: the bladder's material laws (avbdl.h): Pipan et al.'s Mooney-Rivlin stress
// and work, Eq. (20)-(22), the Gent-Gent law for a tube inflated far past Eq. (20)'s range,
// and the free tube's inflation pressure.
#include <cmath>

#include "pam_actuator/avbdl.h"

namespace pamsim {

double mooney_rivlin_stress(const MooneyRivlinConstants& c, double stretch) {
  // Eq. (20), C01 term reconstructed as 2 C01 (1 - 1/lambda^3) (the text lost its fraction
  // bars); it is the one whose integral gives Eq. (22)'s C01 (1 + 2 lambda) term
  const double l = stretch;
  const double i1_minus_3 = l * l + 2.0 / l - 3.0;
  return 2.0 * c.c10_pa * (l - 1.0 / (l * l)) + 2.0 * c.c01_pa * (1.0 - 1.0 / (l * l * l)) +
         4.0 * c.c20_pa * (l - 1.0 / (l * l)) * i1_minus_3;
}

double mooney_rivlin_energy_density(const MooneyRivlinConstants& c, double stretch) {
  // Eq. (22), the integral (21) of (20) from 1 to lambda:
  // (lambda - 1)^2 / lambda^2 [C01 (1 + 2 lambda) + C10 lambda (2 + lambda)]
  //   + C20 (lambda^3 - 3 lambda + 2)^2 / lambda^2
  const double l = stretch;
  const double cubic = l * l * l - 3.0 * l + 2.0;
  const double c10_c01 = c.c01_pa * (1.0 + 2.0 * l) + c.c10_pa * l * (2.0 + l);
  return (l - 1.0) * (l - 1.0) / (l * l) * c10_c01 + c.c20_pa * cubic * cubic / (l * l);
}

double gent_gent_stress(const GentGentConstants& c, double stretch) {
  // P = 2 (lambda - 1/lambda^2) (W1 + W2 / lambda), uniaxial, incompressible:
  // W1 = mu Jm / (2 (Jm - (I1 - 3))), W2 = C2 / I2, I1 = lambda^2 + 2/lambda, I2 = 2 lambda
  // + 1/lambda^2
  const double l = stretch;
  const double i1_minus_3 = l * l + 2.0 / l - 3.0;
  const double i2 = 2.0 * l + 1.0 / (l * l);
  const double w1 = 0.5 * c.mu_pa * c.jm / (c.jm - i1_minus_3);
  return 2.0 * (l - 1.0 / (l * l)) * (w1 + c.c2_pa / (i2 * l));
}

double gent_gent_energy_density(const GentGentConstants& c, double stretch) {
  const double l = stretch;
  const double i1_minus_3 = l * l + 2.0 / l - 3.0;
  const double i2 = 2.0 * l + 1.0 / (l * l);
  return -0.5 * c.mu_pa * c.jm * std::log1p(-i1_minus_3 / c.jm) + c.c2_pa * std::log(i2 / 3.0);
}

double bladder_stress(const AvbdlParams& p, double stretch) {
  return p.bladder_law == BladderLaw::kGentGent ? gent_gent_stress(p.bladder_gent, stretch)
                                                : mooney_rivlin_stress(p.bladder, stretch);
}

double bladder_energy_density(const AvbdlParams& p, double stretch) {
  return p.bladder_law == BladderLaw::kGentGent ? gent_gent_energy_density(p.bladder_gent, stretch)
                                                : mooney_rivlin_energy_density(p.bladder, stretch);
}

double avbdl_bladder_reference_radius(const AvbdlParams& p) {
  if (p.bladder_diameter_m > 0.0) return 0.5 * p.bladder_diameter_m - 0.5 * p.wall_thickness_m;
  return 0.5 * p.diameter_m;
}

double avbdl_bladder_free_pressure(const AvbdlParams& p, double radius_m) {
  const double rb = avbdl_bladder_reference_radius(p);
  const double stretch = radius_m / rb;
  return bladder_stress(p, stretch) * p.wall_thickness_m / (stretch * rb);
}

double avbdl_bladder_contact_pressure(const AvbdlParams& p) {
  return avbdl_bladder_free_pressure(p, 0.5 * p.diameter_m);
}

}  // namespace pamsim
