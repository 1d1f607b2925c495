// avbdl_validation.cc: the checks of an AVBDL plant's parameters (validate_avbdl_params)
// and the parameters of a muscle from its geometry (avbdl_params_from_geometry), see
// avbdl.h. Each check throws InputError "<key> must be ..., got <value>".
#include <cmath>
#include <string>
#include <utility>

#include "base/format.h"
#include "base/input_error.h"
#include "pam_actuator/avbdl.h"

namespace pamsim {
namespace {

// one "<key> must be ..., got <value>" check
struct Checker {
  const std::string& prefix;
  void require(bool ok, const std::string& key, const std::string& allowed, double v) const {
    require_value(ok, prefix + key, allowed, v);
  }
  void finite(const std::string& key, double v) const {
    require(std::isfinite(v), key, "finite", v);
  }
  void non_negative(const std::string& key, double v) const {
    require(v >= 0.0, key, ">= 0", v);
  }
};

void validate_friction(const AvbdlFriction& f, const Checker& check) {
  const std::pair<const char*, const AvbdlFrictionCoefficients*> branches[] = {
      {"friction.extension.", &f.extension}, {"friction.contraction.", &f.contraction}};
  for (const auto& [name, c] : branches) {
    const std::string key(name);
    check.finite(key + "force_n", c->force_n);
    check.non_negative(key + "force_n", c->force_n);
    check.finite(key + "pressure_area_m2", c->pressure_area_m2);
    check.non_negative(key + "pressure_area_m2", c->pressure_area_m2);
    check.finite(key + "strain_area_m2", c->strain_area_m2);
    check.non_negative(key + "strain_area_m2", c->strain_area_m2);
  }
  check.finite("friction.velocity_scale_m_per_s", f.velocity_scale_m_per_s);
  check.require(f.velocity_scale_m_per_s > 0.0, "friction.velocity_scale_m_per_s", "> 0 m/s",
                f.velocity_scale_m_per_s);
  if (f.model == FrictionModel::kMaxwellSlip) {
    validate_maxwell_slip(f.slip, check.prefix + "friction.");
  }
}

// The Gent-Gent law's constants, and a tube bladder (bladder_diameter_m > 0) that fits in
// its sleeve, holds its wall, and can reach the braid short of the Gent-Gent limit
void validate_bladder_tube(const AvbdlParams& p, const Checker& check) {
  check.finite("bladder_diameter_m", p.bladder_diameter_m);
  check.require(p.bladder_diameter_m == 0.0 ||
                    (p.bladder_diameter_m > 2.0 * p.wall_thickness_m &&
                     p.bladder_diameter_m <= p.diameter_m),
                "bladder_diameter_m",
                "0 (the braid's) or in (2 wall = " + format_value(2.0 * p.wall_thickness_m) +
                    ", diameter = " + format_value(p.diameter_m) + "] m",
                p.bladder_diameter_m);
  validate_bladder_relaxation(p.relaxation, check.prefix + "bladder.");
  if (p.bladder_law != BladderLaw::kGentGent) return;
  const GentGentConstants& g = p.bladder_gent;
  check.finite("bladder.mu_pa", g.mu_pa);
  check.finite("bladder.c2_pa", g.c2_pa);
  check.finite("bladder.jm", g.jm);
  check.require(g.mu_pa > 0.0, "bladder.mu_pa", "> 0 Pa", g.mu_pa);
  check.non_negative("bladder.c2_pa", g.c2_pa);
  check.require(g.jm > 0.0, "bladder.jm", "> 0", g.jm);
  // the tube must reach the braid at L0 short of its limit (R0 / rb is its least stretch)
  const double stretch = 0.5 * p.diameter_m / avbdl_bladder_reference_radius(p);
  const double i1_minus_3 = stretch * stretch + 2.0 / stretch - 3.0;
  check.require(i1_minus_3 < 0.999 * g.jm, "bladder_diameter_m",
                "large enough that the sleeve stretches it short of the Gent-Gent limit (I1 - 3 "
                "= " + format_value(i1_minus_3) + " at stretch " + format_value(stretch) +
                    ", 0.999 Jm = " + format_value(0.999 * g.jm) + ")",
                p.bladder_diameter_m);
}

}  // namespace

void validate_avbdl_params(const AvbdlParams& p, const std::string& key_prefix) {
  const Checker check{key_prefix};

  // every number finite
  check.finite("length_m", p.length_m);
  check.finite("diameter_m", p.diameter_m);
  check.finite("braid_angle_rad", p.braid_angle_rad);
  check.finite("wall_thickness_m", p.wall_thickness_m);
  check.finite("bladder.c10_pa", p.bladder.c10_pa);
  check.finite("bladder.c01_pa", p.bladder.c01_pa);
  check.finite("bladder.c20_pa", p.bladder.c20_pa);
  check.finite("end_length_m", p.end_length_m);
  check.finite("end_slope", p.end_slope);

  // geometry: dimensions, and a braid that contracts from L0 (b > L0, L0 > b / sqrt 3)
  check.require(p.length_m > 0.0, "length_m", "> 0 m", p.length_m);
  check.require(p.diameter_m > 0.0, "diameter_m", "> 0 m", p.diameter_m);
  const double max_angle = std::acos(1.0 / std::sqrt(3.0));
  check.require(p.braid_angle_rad > 0.0 && p.braid_angle_rad < max_angle, "braid_angle_rad",
                "in (0, " + format_value(max_angle) +
                    ") rad (fibre longer than L0, braid able to contract from L0)",
                p.braid_angle_rad);
  check.require(p.wall_thickness_m >= 0.0, "wall_thickness_m", ">= 0 m", p.wall_thickness_m);

  // bladder material, Eq. (20)
  check.require(p.bladder.c10_pa + p.bladder.c01_pa > 0.0, "bladder.c10_pa",
                "> -bladder.c01_pa = " + format_value(-p.bladder.c01_pa) +
                    " Pa (a positive initial shear modulus 2 (C10 + C01))",
                p.bladder.c10_pa);
  check.non_negative("bladder.c20_pa", p.bladder.c20_pa);
  validate_bladder_tube(p, check);

  // end regions: both fit in the muscle at its free-contraction length b / sqrt 3
  const double l_min = avbdl_braid(p).fibre_length_m / std::sqrt(3.0);
  check.require(p.end_length_m >= 0.0 && 2.0 * p.end_length_m < l_min, "end_length_m",
                "in [0, " + format_value(0.5 * l_min) + ") m (half the fully contracted length)",
                p.end_length_m);
  check.require(p.end_slope >= 0.0 && p.end_slope <= 3.0, "end_slope",
                "in [0, 3] (a monotone end profile)", p.end_slope);

  validate_friction(p.friction, check);
}

AvbdlParams avbdl_params_from_geometry(double length_m, double diameter_m,
                                       double braid_angle_rad, double wall_thickness_m,
                                       const MooneyRivlinConstants& bladder,
                                       const std::string& key_prefix) {
  AvbdlParams p;
  p.length_m = length_m;
  p.diameter_m = diameter_m;
  p.braid_angle_rad = braid_angle_rad;
  p.wall_thickness_m = wall_thickness_m;
  p.bladder = bladder;
  p.end_length_m = kAvbdlEndFraction * length_m;   // end slope and friction: the defaults
  validate_avbdl_params(p, key_prefix);
  return p;
}

}  // namespace pamsim
