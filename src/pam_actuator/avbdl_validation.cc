// avbdl_validation.cc: the checks of an AVBDL plant's parameters (validate_avbdl_params)
// and the parameters of a muscle from its geometry (avbdl_params_from_geometry), see
// avbdl.h. Each key's own range is its row's (avbdl_keys.h); the checks that join keys are
// here, named by the same keys in the same units. Each throws InputError
// "<key> must be ..., got <value>".
#include <cmath>
#include <string>

#include "base/format.h"
#include "base/input_error.h"
#include "base/units.h"
#include "pam_actuator/avbdl.h"
#include "pam_actuator/avbdl_keys.h"

namespace pamsim {
namespace {

// The bladder's checks that join keys: a positive initial shear modulus (Eq. (20)), a tube
// (diameter > 0) that fits in its sleeve and holds its wall, and a Gent-Gent tube the
// sleeve stretches short of the law's limit
void validate_bladder(const AvbdlParams& p, const std::string& prefix) {
  require_value(p.bladder.c10_pa + p.bladder.c01_pa > 0.0, prefix + "bladder.C10_MPa",
                "> -bladder.C01_MPa = " + format_value(-units::pa_to_mpa(p.bladder.c01_pa)) +
                    " MPa (a positive initial shear modulus 2 (C10 + C01))",
                units::pa_to_mpa(p.bladder.c10_pa));
  const std::string diameter = prefix + "bladder.diameter_mm";
  require_value(
      p.bladder_diameter_m == 0.0 ||
          (p.bladder_diameter_m > 2.0 * p.wall_thickness_m && p.bladder_diameter_m <= p.diameter_m),
      diameter,
      "0 (the sleeve's) or in (2 wall = " + format_value(units::m_to_mm(2.0 * p.wall_thickness_m)) +
          ", diameter = " + format_value(units::m_to_mm(p.diameter_m)) + "] mm",
      units::m_to_mm(p.bladder_diameter_m));
  validate_bladder_relaxation(p.relaxation, prefix + "bladder.");
  if (p.bladder_law != BladderLaw::kGentGent) return;
  // the tube must reach the braid at L0 short of its limit (R0 / rb is its least stretch)
  const double stretch = 0.5 * p.diameter_m / avbdl_bladder_reference_radius(p);
  const double i1_minus_3 = stretch * stretch + 2.0 / stretch - 3.0;
  require_value(i1_minus_3 < 0.999 * p.bladder_gent.jm, diameter,
                "large enough that the sleeve stretches it short of the Gent-Gent limit (I1 - 3 "
                "= " +
                    format_value(i1_minus_3) + " at stretch " + format_value(stretch) +
                    ", 0.999 Jm = " + format_value(0.999 * p.bladder_gent.jm) + ")",
                units::m_to_mm(p.bladder_diameter_m));
}

}  // namespace

void validate_avbdl_params(const AvbdlParams& p, const std::string& key_prefix) {
  AvbdlParams read = p;  // the rows bind a struct they could write; here they only read it
  for (const KeyTable& table : avbdl_key_tables(&read)) {
    try {
      check_key_rows(table);
    } catch (const InputError& e) {
      const InputErrorParts& parts = e.parts();
      throw InputError(key_prefix + e.what(), {"", key_prefix + parts.key, parts.problem});
    }
  }
  validate_bladder(p, key_prefix);
  // end regions: both fit in the muscle at its free-contraction length b / sqrt 3
  const double l_min = avbdl_braid(p).fibre_length_m / std::sqrt(3.0);
  require_value(2.0 * p.end_length_m < l_min, key_prefix + "geometry.end_length_mm",
                "in [0, " + format_value(units::m_to_mm(0.5 * l_min)) +
                    ") mm (half the fully contracted length)",
                units::m_to_mm(p.end_length_m));
  if (p.friction.model == FrictionModel::kMaxwellSlip) {
    validate_maxwell_slip(p.friction.slip, key_prefix + "friction.");
  }
}

AvbdlParams avbdl_params_from_geometry(double length_m, double diameter_m, double braid_angle_rad,
                                       double wall_thickness_m,
                                       const MooneyRivlinConstants& bladder,
                                       const std::string& key_prefix) {
  AvbdlParams p;
  p.length_m = length_m;
  p.diameter_m = diameter_m;
  p.braid_angle_rad = braid_angle_rad;
  p.wall_thickness_m = wall_thickness_m;
  p.bladder = bladder;
  p.end_length_m = kAvbdlEndFraction * length_m;  // end slope and friction: the defaults
  validate_avbdl_params(p, key_prefix);
  return p;
}

}  // namespace pamsim
