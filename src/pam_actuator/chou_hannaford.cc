// chou_hannaford.cc: see chou_hannaford.h.
#include "pam_actuator/chou_hannaford.h"

#include <cmath>
#include <string>

#include "base/input_error.h"
#include "base/units.h"

namespace pamsim {

BraidGeometry braid_from_initial_shape(double length_m, double diameter_m, double braid_angle_rad) {
  if (!(length_m > 0.0)) {
    throw InputError("braid geometry: length must be > 0 m, got " + std::to_string(length_m));
  }
  if (!(diameter_m > 0.0)) {
    throw InputError("braid geometry: diameter must be > 0 m, got " + std::to_string(diameter_m));
  }
  if (!(braid_angle_rad > 0.0 && braid_angle_rad < 0.5 * units::kPi)) {
    throw InputError("braid geometry: braid angle must be in (0, 90) deg, got " +
                     std::to_string(units::rad_to_deg(braid_angle_rad)));
  }
  BraidGeometry g;
  g.fibre_length_m = length_m / std::cos(braid_angle_rad);
  g.turns = g.fibre_length_m * std::sin(braid_angle_rad) / (units::kPi * diameter_m);
  return g;
}

double chou_hannaford_volume(const BraidGeometry& g, double length_m) {
  const double b = g.fibre_length_m;
  const double n = g.turns;
  return length_m * (b * b - length_m * length_m) / (4.0 * units::kPi * n * n);
}

double chou_hannaford_diameter(const BraidGeometry& g, double length_m) {
  const double b = g.fibre_length_m;
  const double squared = b * b - length_m * length_m;
  return squared > 0.0 ? std::sqrt(squared) / (units::kPi * g.turns) : 0.0;
}

double chou_hannaford_dvolume_dlength(const BraidGeometry& g, double length_m) {
  const double b = g.fibre_length_m;
  const double n = g.turns;
  return (b * b - 3.0 * length_m * length_m) / (4.0 * units::kPi * n * n);
}

double chou_hannaford_force(const BraidGeometry& g, double p_pa, double length_m) {
  return -p_pa * chou_hannaford_dvolume_dlength(g, length_m);
}

}  // namespace pamsim
