// pam_params.h: one PAM's parameter file (TOML, the paper's units named in the file),
// read once, validated, converted to SI. Shipped files live in models/pams/; the file's
// layout is shown at load_pam_params.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "base/key_table.h"
#include "pam_actuator/spring_model.h"

namespace pamsim {

struct StrainGaugeParams {
  double q_v_per_n = 0.0;  // Eq. (8) slope [V/N], > 0
  double v_base_v = 0.0;   // Eq. (8) offset [V]
};

struct PamGeometry {
  double length_m = 0.0;           // unpressurised braided length L0
  double sleeve_diameter_m = 0.0;  // D0
  double bladder_diameter_m = 0.0;
  double braid_angle_rad = 0.0;  // alpha0, to the muscle axis
};

struct PamParams {
  std::string name;
  std::string source;  // where the numbers come from
  SpringModel spring;
  std::optional<StrainGaugeParams> strain_gauge;
  std::optional<PamGeometry> geometry;
};

// A parameter file:
//   name = "agonist"
//   source = "Yoshida & Hosoda, Table IV"
//   [spring]
//   law = "eq3"                                   # eq3 | eq4 | eq5
//   units = { pressure = "MPa", length = "mm", force = "N" }
//   m = -60.1                                     # Eq. (2) slope [mm/MPa]
//   h = 170.1                                     # Eq. (2) intercept [mm]
//   a0 = 0.911  a1 = 0.256  a2 = 7.00  a3 = -0.201   (b0..b5 for eq4, c0..c4 for eq5)
//   [strain_gauge]                                # optional, Eq. (8)
//   q_V_per_N = 2.25e-3
//   V_base_V = 0.0                                # optional, default 0
//   [geometry]                                    # optional, Table I; for the chamber volume
//   length_mm = 180  sleeve_diameter_mm = 16.0  bladder_diameter_mm = 4.0  braid_angle_deg = 25
// Reads and validates a parameter file. Throws InputError naming the file and key for a
// missing file, a TOML syntax error, an unknown key, a missing coefficient, a wrong unit,
// or a non-finite / out-of-range value.
PamParams load_pam_params(const std::string& path);

// Checks a spring law and gauge given in code (not read from a file) against the parameter
// file's own rows, in the paper's units: the law's coefficients finite, h > 0, q > 0. Throws
// InputError "<key_prefix>.spring.h must be in (0, inf) mm, got -1" and the like.
void validate_pam_params(const SpringModel& spring, const StrainGaugeParams& gauge,
                         const std::string& key_prefix);

// The TOML text of `params` in the same format (paper units), for `fit -o`.
std::string pam_params_to_toml(const PamParams& params);

// Every key of a parameter file (its table, unit, default, range and meaning), from the rows
// its reader reads: `pamsim keys --params`.
std::vector<KeyDoc> pam_key_docs();

}  // namespace pamsim
