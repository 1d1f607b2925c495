// length_estimation.h: the papers' length-estimation validation (Yoshida and Hosoda,
// Sec. II-B, III-B, Table III) as a protocol over data. For each virtual PAM: the static
// tensile test on its plant (pam_actuator/tensile_test.h), the least-squares fits of Eq. (3),
// (4) and (5) (identification.h), then the dynamic test on the pulley rig, one trial per
// fitted law and weight, the length estimated by that law against the rig's true length.
// The protocol is a file (scenarios/validate_length_estimation.toml; its keys at
// load_length_validation).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pam_actuator/identification.h"
#include "pam_actuator/pam_params.h"
#include "pam_actuator/plant_params.h"
#include "pam_actuator/tensile_test.h"
#include "sim/core/trial.h"
#include "sim/validate/bands.h"
#include "sim/validate/error_budget.h"
#include "sim/validate/validation_options.h"

namespace pamsim {

struct ValidationPam {
  std::string name;  // "A"
  std::string plant_file;
  PlantParams plant;
  double bladder_diameter_m = 0.0;        // Table I, for the estimator's [geometry]
  TensileTestOptions tensile;             // pressures and maximum deformation set per PAM
  double offset_mpa = 0.0;                // the dynamic test's sine offset
  std::map<std::string, ErrorPct> paper;  // by law name ("eq3"); absent: not published
  // changes of its plant's fields ("bladder.C20_MPa=0.01", the file's units) that `plant`
  // holds, for the rig's trials as muscles.pam.plant.<table>.<field> (with_plant_changes)
  std::vector<std::string> plant_changes;
};

struct LengthValidationSpec {
  std::string file;
  std::string rig_file;
  std::vector<std::string> overrides;
  std::vector<SpringLaw> laws;
  std::vector<double> weights_kg;
  StrainGaugeParams gauge;  // from tensile.sensors_from
  std::string gauge_file;
  std::vector<ValidationPam> pams;
  std::vector<std::string> pam_names;  // every PAM of the file, asked for or not
  std::vector<BudgetSource> budget;    // [[budget_source]]
  std::vector<Bracket> brackets;       // [[bracket]]: the rig's unsized parts (bands.h)
  std::uint64_t bracket_seed = 1;
};

// The protocol file's keys, paths relative to it:
//   rig                 the dynamic test's scenario (the pulley rig), required
//   overrides           scenario overrides for every dynamic trial ("key=value" strings)
//   laws                ["eq3", "eq4", "eq5"] or a subset
//   weights_kg          the hanging weights, each in (0, 1000]
//   [tensile]           step_mm (> 0), noise_pressure_MPa, noise_force_N, noise_length_mm
//                       (>= 0), seed (>= 0), sensors_from: a PAM file whose [strain_gauge]
//                       (Eq. (8)) the fitted estimators get
//   [pams.<NAME>]       plant (file), bladder_diameter_mm (Table I, > 0), pressures_MPa (the
//                       test's, >= 3 distinct for Eq. (4)), max_deformation_mm (> step),
//                       offset_MPa (the sine's, Eq. (6)-(7)), paper = { eq3 = [max, RMSE],
//                       ... } (Table III, % of length; optional)
//   [[budget_source]]   the hardware's error sources for --budget (error_budget.h)
//   [[bracket]], bracket_seed  the rig's unsized parts for --bands, --sensitivity (bands.h)
// Each PAM's dynamic trials set muscles.pam.plant, muscles.pam.params (the fit, written as
// a PAM file), bodies.weight.mass_kg and muscles.pam.command.offset_MPa on the rig.
// Reads and validates the protocol, with `protocol_overrides` ("key=value" of the protocol
// file's own keys) applied first; `only` keeps the named PAMs, in that order (empty: all).
// Throws InputError "<file>: <key> <problem>" (or "--pams: unknown PAM X, the file has A, B").
LengthValidationSpec load_length_validation(
    const std::string& path, const std::vector<std::string>& only = {},
    const std::vector<std::string>& protocol_overrides = {});

// Takes the overrides pams.<NAME>.plant.<table>.<field>=<value> out of `overrides` (a --set
// or a [[bracket]]'s draw: a change of that PAM's plant file, in its units) and returns the
// spec whose PAMs hold their changed plants, for the tensile test and fits and the rig's
// trials alike: the lab fits the PAM it has. A PAM the spec does not hold (--pams) is left
// out. Throws InputError "--set <override>: ..." for another pams.* key, a PAM not in the
// file, or a change the plant file refuses (named "pams.<NAME>.plant.<key>").
LengthValidationSpec with_plant_changes(const LengthValidationSpec& spec,
                                        std::vector<std::string>* overrides);

struct FittedLaw {
  std::string pam;
  SpringLaw law = SpringLaw::kEq3;
  SpringFit fit;
  std::string params_file;      // out_dir/fits/pam_<NAME>_<law>.toml
  double max_residual_n = 0.0;  // largest |f - law(p, d)| over the test's rows
};

struct DynamicRow {
  std::string pam;
  SpringLaw law = SpringLaw::kEq3;
  double weight_kg = 0.0;
  std::string status;  // the trial's ("ok", "diverged")
  ErrorPct sim;        // over the whole trial
  std::optional<ErrorPct> paper;
  Trajectory trajectory;  // for the figures
};

struct LengthValidationResult {
  std::vector<std::vector<TensileRow>> tensile;  // per PAM, the spec's order
  std::vector<FittedLaw> fits;                   // PAM-major, the spec's law order
  std::vector<DynamicRow> rows;                  // PAM, then law, then weight
  std::string fits_dir;                          // where the fitted files are now
};

// Runs the protocol: tensile tests and fits, then the dynamic trials on `threads` threads.
// The fitted PAM files, which the trials' scenarios name, are written to a temp folder in
// out_dir (result.fits_dir), which write_length_validation moves into place; on any error
// the temp folder is removed. Throws InputError for bad overrides (a --set of a key the
// protocol sets per trial among them) before any trial runs.
LengthValidationResult run_length_validation(const LengthValidationSpec& spec,
                                             const ValidationOptions& options);

// out_dir/table3.csv (one row per PAM, law and weight: pam, law, weight_kg, status,
// max_error_pct, rmse_pct, paper_max_error_pct, paper_rmse_pct, fit_rmse_N,
// fit_max_residual_N, fit_r2), out_dir/table3.md (Table III's layout per weight, the
// paper's values beside) and per PAM out_dir/pam_<NAME>.png (Fig. 5-6: true and Eq. (3)
// estimated length over time, and every law's error); then the fits folder becomes
// out_dir/fits (an older one replaced). Each file appears whole or not at all; on failure
// the temp fits folder is removed and an older fits/ stays. Without `plots`, no PNG.
void write_length_validation(LengthValidationResult& result, const LengthValidationSpec& spec,
                             const std::string& out_dir, bool plots = true);

// The table texts, for tests: the same bytes as the files.
std::string table3_csv(const LengthValidationResult& result);
std::string table3_markdown(const LengthValidationResult& result, const LengthValidationSpec& spec);

}  // namespace pamsim
