// protocol_budgets.h: the error budget (error_budget.h) of each validation protocol, run by
// `pamsim validate length-estimation --budget` and `validate reaching --budget`. Each
// configuration of the budget runs the whole protocol with the same seeds, so two runs
// differ only by the sources they turn on (the hardware models draw from generators of
// their own: turning one on moves no other source's noise).
#pragma once

#include "sim/validate/error_budget.h"
#include "sim/validate/length_estimation.h"
#include "sim/validate/reaching.h"

namespace pamsim {

// Table III's headline cells: each PAM of the spec with the protocol's first law at its
// first weight (Eq. (3), 5 kg in the shipped file), named "PAM-<NAME>". Throws InputError
// "<file>: budget_source ..." when the file has no source, and for a source the rig refuses
// (check_budget_sources), before any trial runs.
ErrorBudget run_length_budget(const LengthValidationSpec& spec, const ValidationOptions& options);

// Table V's cells over the whole window: per muscle the model estimate and the fiber
// sensor, named "<muscle> model" and "<muscle> fiber". Throws like run_length_budget.
ErrorBudget run_reaching_budget(const ReachingValidationSpec& spec,
                                const ValidationOptions& options);

}  // namespace pamsim
