// muscle_law.h: the static law of a scenario muscle's plant, whichever it is: its plant
// file's AVBDL law (pam_actuator/avbdl.h) when muscles.<m>.plant is given, else the spring
// law of its params file (plant = estimator, Eq. (1)-(5)). What solves lines (calibration,
// line = "equilibrium") must use the plant, as the co-simulation does; what estimates must
// use the params file's law, as the sensors do.
#pragma once

#include "sim/core/scenario.h"

namespace pamsim {

// The PAM length [m] at which the plant pulls nothing at gauge pressure p [Pa].
double plant_free_length(const MuscleSpec& muscle, double p_pa);
// The plant's pull [N] at rest at gauge pressure p [Pa] and PAM length l [m]; >= 0.
double plant_static_force(const MuscleSpec& muscle, double p_pa, double length_m);
// The PAM length [m] at which the plant pulls f > 0 [N] at rest, or -1 if it cannot.
double plant_length_at_force(const MuscleSpec& muscle, double p_pa, double f_n);

}  // namespace pamsim
