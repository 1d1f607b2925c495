// line_breaks.h: a validation rig whose fishing line would break is not a rig a lab could
// run. A muscle's line breaks at muscles.<m>.line_strength_MPa times its section
// (MuscleSpec::line_break_n); both protocols (length_estimation.h, reaching.h) refuse a rig
// whose logged tension passes it, and the bands count such a rig as refused (bands.h).
#pragma once

#include <string>
#include <vector>

#include "sim/core/scenario.h"
#include "sim/core/trial_log.h"

namespace pamsim {

// Throws InputError (the scenario's file, muscles.<m>.line_strength_MPa, "its line breaks: it
// pulls F N, past its break load of B N") where a muscle with a break load pulls past it in
// any of `trajectories` (each with its force_<label>_N column), the settling included.
void check_line_breaks(const Scenario& sc, const std::vector<const Trajectory*>& trajectories);

// The largest pull of muscle `m`'s line in `trajectories` (their force_<label>_N columns).
double logged_peak_tension(const MuscleSpec& m, const std::vector<const Trajectory*>& trajectories);

// "its line breaks: it pulls F N, past its break load of B N" where `peak_n` passes m's break
// load; "" where it stays within it, or m's line has none.
std::string line_break_problem(const MuscleSpec& m, double peak_n);

}  // namespace pamsim
