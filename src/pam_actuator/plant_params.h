// plant_params.h: a muscle's physical plant, read from its own file (models/pams/plant_*.toml),
// apart from the spring law its estimator inverts (pam_params.h): the simulated muscle is
// physics, the estimator a fit to it. Today one law, AVBDL (avbdl.h, Pipan et al.); the
// file's layout is shown at load_plant_params.
#pragma once

#include <string>
#include <vector>

#include <toml++/toml.h>

#include "base/key_table.h"
#include "pam_actuator/avbdl.h"

namespace pamsim {

struct PlantParams {
  std::string name;
  std::string source;
  AvbdlParams avbdl;
};

// A plant file, in the papers' units:
//   name = "agonist"
//   source = "..."                      # where the numbers come from
//   law = "avbdl"
//   [geometry]
//   length_mm = 180                     # L0, unpressurised
//   diameter_mm = 16                    # D0
//   braid_angle_deg = 25                # alpha0, to the axis, < 54.74
//   wall_thickness_mm = 1.0             # bladder wall, >= 0
//   end_length_mm = 28.8                # optional: default 0.16 L0 (the DMSP-20's 32 of 200),
//                                       # 3.2 R0 with bladder.diameter_mm (its 32 at 10 mm)
//   end_slope = 2.0                     # optional: the end profile's shape a in [0, 3]
//   [bladder]
//   material = "natural_rubber"         # or "silicone", or the constants:
//   C10_MPa = 0.05  C01_MPa = 0.18  C20_MPa = 0.0035
//   law = "mooney_rivlin"               # optional (default), or "gent_gent": natural
//                                       # rubber's fit, or mu_MPa, C2_MPa, Jm (avbdl.h)
//   diameter_mm = 4.0                   # optional: a tube this wide (outer) inside the
//                                       # sleeve, Table I; default: the sleeve's (avbdl.h)
//   relaxation_weights = [0.07, 0.07]   # optional: the rubber's Prony series g_i >= 0
//   relaxation_times_s = [0.01, 0.1]    # and tau_i > 0 [s], 0-4 terms (bladder_relaxation.h)
//   [friction]                          # optional: none when absent
//   model = "smooth"                    # tanh(v / v_s) (default), or "maxwell_slip"
//   velocity_scale_mm_s = 1.0           # v_s: required for "smooth"
//   breakaway_mm = [0.1, 0.5]           # "maxwell_slip" only: 1-4 elements' travels
//   weights = [0.5, 0.5]                # and their shares of F_f, summing to 1
//   extension = { F0_N = 0.5, A0_mm2 = 1.0, A1_mm2 = 0.0 }
//   contraction = { F0_N = 0.5, A0_mm2 = 1.0, A1_mm2 = 0.0 }
//
// Reads and validates a plant file. Throws InputError "<path>: <key>: <problem>" for a
// missing file, a syntax error, an unknown key, a missing or non-finite value, or
// dimensions that cannot be (a braid angle impossible for the length, a negative friction).
PlantParams load_plant_params(const std::string& path);

// The same with `changes` (tables and values of the file's own layout, in its units: e.g.
// geometry.wall_thickness_mm) written over the file's, each validated as the file's own: a
// scenario's muscles.<m>.plant.<table>.<field> keys. A refused change is
// named "<prefix><key>: <problem>" (prefix "muscles.agonist.plant."), a refused value of the
// file as above.
PlantParams load_plant_params(const std::string& path, const toml::table& changes,
                              const std::string& prefix);

// Every key of a plant file (its table, unit, default, range and meaning), from the rows its
// reader reads (avbdl_keys.h and the file's own): `pamsim keys --plant`.
std::vector<KeyDoc> plant_key_docs();

}  // namespace pamsim
