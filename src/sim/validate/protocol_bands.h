// protocol_bands.h: the bands and the sensitivity (bands.h) of each validation protocol, run
// by `pamsim validate length-estimation|reaching --bands N` and `--sensitivity`. Every run has
// each [[budget_source]] on (the budget's "all" run: the lab's rig has all its hardware),
// then the user's --set, then the brackets' values. Rig r runs with seed (--seed, default 1)
// + r times the protocol's trials per run, so the rigs differ in their noise as well.
#pragma once

#include "sim/validate/bands.h"
#include "sim/validate/length_estimation.h"
#include "sim/validate/reaching.h"

namespace pamsim {

// Table III's cells (each PAM, law and weight: "PAM-A eq3 5 kg") over `rigs` drawn rigs.
// Throws InputError "<file>: bracket ..." for a file without brackets or a bracket the rig
// refuses (check_brackets), and "--bands must be in [1, 10000]", before any trial runs.
Bands run_length_bands(const LengthValidationSpec& spec, const ValidationOptions& options,
                       int rigs);
Sensitivity run_length_sensitivity(const LengthValidationSpec& spec,
                                   const ValidationOptions& options);

// Table V's cells (each muscle, method and part: "agonist model all") likewise.
Bands run_reaching_bands(const ReachingValidationSpec& spec, const ValidationOptions& options,
                         int rigs);
Sensitivity run_reaching_sensitivity(const ReachingValidationSpec& spec,
                                     const ValidationOptions& options);

inline constexpr int kMaxBandRigs = 10000;
// Throws InputError "--bands must be in [1, 10000], got <rigs>".
void check_band_rigs(int rigs);

}  // namespace pamsim
