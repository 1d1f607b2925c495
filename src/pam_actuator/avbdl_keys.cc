// avbdl_keys.cc: the AVBDL plant's key rows (avbdl_keys.h). Equation numbers are Pipan et al.'s.
#include "pam_actuator/avbdl_keys.h"

#include <cmath>
#include <limits>
#include <string>

#include "base/units.h"

namespace pamsim {
namespace {

constexpr double kMm = units::kMPerMm;
constexpr double kMPa = units::kPaPerMPa;

// alpha0 below arccos(1 / sqrt 3): a braid at a steeper angle cannot contract from L0
KeyRange braid_angle_range() {
  return {0.0, units::rad_to_deg(std::acos(1.0 / std::sqrt(3.0))), true, true};
}

KeyTable geometry_table(AvbdlParams* a) {
  KeyTable t{"geometry", {}, {}};
  t.numbers = {{"length_mm", "mm", kMm, kPositiveRange,
                "L0: the muscle's length unpressurised, fitting to "
                "fitting",
                &a->length_m, nullptr, true},
               {"diameter_mm", "mm", kMm, kPositiveRange, "D0: the braid's diameter at L0",
                &a->diameter_m, nullptr, true},
               {"braid_angle_deg", "deg", units::kPi, braid_angle_range(),
                "alpha0: the braid's angle to the axis at L0", &a->braid_angle_rad, nullptr, true,
                "", 180.0},
               {"wall_thickness_mm", "mm", kMm, kNonNegativeRange,
                "t: the bladder's wall (0: no bladder "
                "loss, Eq. (23)-(24))",
                &a->wall_thickness_m, nullptr, true},
               {"end_length_mm", "mm", kMm, kNonNegativeRange,
                "Ld: each end region's length (Eq. (27)-(29)); "
                "both must fit in the fully contracted muscle",
                &a->end_length_m, nullptr, false,
                "(0.16 L0, the DMSP-20's 32 of 200; 3.2 R0 with bladder.diameter_mm)"},
               {"end_slope",
                "",
                1.0,
                {0.0, 3.0},
                "a: the end profile's shape (Eq. (6)); 2: a parabolic "
                "shoulder",
                &a->end_slope}};
  return t;
}

KeyTable bladder_table(AvbdlParams* a) {
  KeyTable t{"bladder", {}, {}};
  t.choices = {{"law",
                {"mooney_rivlin", "gent_gent"},
                "the rubber's law: Mooney-Rivlin (Pipan et al. 2025, Eq. (20)), or Gent-Gent "
                "(Pucci and Saccomandi 2002) for a tube's large stretch",
                [a](const std::string& v) {
                  a->bladder_law =
                      v == "gent_gent" ? BladderLaw::kGentGent : BladderLaw::kMooneyRivlin;
                },
                [a] {
                  return std::string(a->bladder_law == BladderLaw::kGentGent ? "gent_gent"
                                                                             : "mooney_rivlin");
                }}};
  const std::string mr = "law = \"mooney_rivlin\": Eq. (20)'s ";  // Pipan et al. 2025
  const std::string gg = "law = \"gent_gent\": ";
  const std::string from_material = "(material's)";
  t.numbers = {{"C10_MPa", "MPa", kMPa, kAnyRange, mr + "C10 (C10 + C01 > 0)", &a->bladder.c10_pa,
                nullptr, false, from_material},
               {"C01_MPa", "MPa", kMPa, kAnyRange, mr + "C01", &a->bladder.c01_pa, nullptr, false,
                from_material},
               {"C20_MPa", "MPa", kMPa, kNonNegativeRange, mr + "C20", &a->bladder.c20_pa, nullptr,
                false, from_material},
               {"mu_MPa", "MPa", kMPa, kPositiveRange, gg + "the shear modulus mu",
                &a->bladder_gent.mu_pa, nullptr, false, from_material},
               {"C2_MPa", "MPa", kMPa, kNonNegativeRange, gg + "C2, the I2 term",
                &a->bladder_gent.c2_pa, nullptr, false, from_material},
               {"Jm", "", 1.0, kPositiveRange, gg + "the limit Jm of I1 - 3", &a->bladder_gent.jm,
                nullptr, false, from_material},
               {"diameter_mm", "mm", kMm, kNonNegativeRange,
                "Db: a tube this wide (outer) inside the sleeve, "
                "Table I of the arm's paper; 0: the sleeve's",
                &a->bladder_diameter_m}};
  return t;
}

KeyTable friction_table(AvbdlParams* a) {
  KeyTable t{"friction", {}, {}};
  t.choices = {{"model",
                {"smooth", "maxwell_slip"},
                "the fibres' friction: tanh(v / v_s) of the rate, or Maxwell-slip elements",
                [a](const std::string& v) {
                  a->friction.model =
                      v == "maxwell_slip" ? FrictionModel::kMaxwellSlip : FrictionModel::kSmooth;
                },
                [a] {
                  return std::string(
                      a->friction.model == FrictionModel::kMaxwellSlip ? "maxwell_slip" : "smooth");
                }}};
  t.numbers = {{"velocity_scale_mm_s", "mm/s", kMm, kPositiveRange,
                "v_s of model = \"smooth\"'s tanh", &a->friction.velocity_scale_m_per_s}};
  return t;
}

// one stroke direction's friction, F0 + (A0 + A1 eps) p
KeyTable stroke_table(const std::string& name, AvbdlFrictionCoefficients* c) {
  KeyTable t{"friction." + name, {}, {}};
  const std::string while_ = name == "extension" ? " while lengthening" : " while shortening";
  t.numbers = {{"F0_N", "N", 1.0, kNonNegativeRange, "F0: the friction at p = 0" + while_,
                &c->force_n, nullptr, true},
               {"A0_mm2", "mm^2", 1e-6, kNonNegativeRange,
                "A0: the friction per pressure at "
                "eps = 0" +
                    while_,
                &c->pressure_area_m2, nullptr, true},
               {"A1_mm2", "mm^2", 1e-6, kNonNegativeRange,
                "A1: A0's growth per unit contraction "
                "strain" +
                    while_,
                &c->strain_area_m2, nullptr, true}};
  return t;
}

}  // namespace

std::vector<KeyTable> avbdl_key_tables(AvbdlParams* plant) {
  return {geometry_table(plant), bladder_table(plant), friction_table(plant),
          stroke_table("extension", &plant->friction.extension),
          stroke_table("contraction", &plant->friction.contraction)};
}

}  // namespace pamsim
