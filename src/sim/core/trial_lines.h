// trial_lines.h: the lines of a trial model's muscles, load_trial_model's part
// (trial_model.cc): each line fixed, or solved so that the start state is static; an
// extensible line a spring in series with its muscle (E A), and a creeping one a Kelvin-Voigt
// element on that spring's compliance; and the start state they are solved in.
#pragma once

#include <string>

#include "sim/core/trial_model.h"

namespace pamsim::detail {

// "<scenario>: <key> <problem>"
[[noreturn]] void fail(const Scenario& sc, const std::string& key, const std::string& problem);

// The start state: the joint at its start position, held bodies in place, at rest, the
// muscles at their first commands.
MjDataPtr start_state(const Scenario& sc, const TrialModel& tm);

// Binds every muscle's line (and its plant's history and its line's creep state in
// d->userdata, after the pressures): fixed ones first, then at most one muscle's solved for a
// static start, then the extensible lines' unstretched lengths, so the start stays as
// calibrated.
void set_lines(const Scenario& sc, TrialModel* tm);

}  // namespace pamsim::detail
