// pam_callback.h: the MuJoCo binding of the PAM force law (Eq. (1)-(5); Pipan et al., Eq. (25)).
//
// MuJoCo 2.2.2 has no plugins: each PAM is a `general` actuator on its tendon with
// biastype="user"; the process-global mjcb_act_bias calls pam_actuator_force, a pure
// function of (m, d, id). What a muscle is (its law, line and the place of its state) is
// bound to the model once (muscle_binding.h); what changes during a trial is in its data:
//   d->userdata[pressure_index]   the chamber gauge pressure [Pa] (the trial's pneumatics)
//   d->userdata[slip_block..]     a Maxwell-slip friction's [L_prev, s_1..s_N]: the muscle
//                                 length at the last committed step (0: none yet, as
//                                 mj_resetData leaves it) and the elements' states
//                                 (maxwell_slip.h)
//   d->userdata[relaxation_block..] a relaxing bladder's [L_prev, F_e(L_prev), h_1..h_N]:
//                                 the committed length (0: none yet), the bladder's relaxed
//                                 force there [N] and the terms' overstresses [N]
//                                 (bladder_relaxation.h)
// The Maxwell-slip and relaxation states move only at pam_commit_history, once per physics
// step; the callback evaluates them as they would be at the step's length, without storing.
// The overstress adds to a taut muscle's pull (a slack one pulls nothing).
//   d->userdata[line.creep_index] a creeping line's creep state q [N] (a Kelvin-Voigt
//                                 element: dq/dt = (F - q) / tau, F the line's tension),
//                                 set to the start's tension by pam_start_line_creep and
//                                 moved by pam_taut_length_committing_creep once per physics step
#pragma once

#include <mujoco/mujoco.h>

#include "pam_actuator/avbdl.h"
#include "pam_actuator/spring_model.h"
#include "sim/core/muscle_binding.h"

namespace pamsim {

// A creeping line's state at the trial's start: the start's tension, held long before it
// (the line's unstretched length was set so, trial_lines.h). A no-op for other lines.
void pam_start_line_creep(const mjModel* m, mjData* d, int actuator_id);
// pam_taut_length of this state; for a creeping line also one physics step of dt_s of its state
// under its tension now (exact for a tension held over the step), from the one tension solve
// both need. A trial's step calls it once per muscle.
double pam_taut_length_committing_creep(const mjModel* m, mjData* d, int actuator_id, double dt_s);

// An extensible line of unstretched length L0 and axial stiffness E A, at tension F, is
// L0 (1 + (F + g q) / (E A)) long (g: its creep, 0 for none; the same Prony form as the
// gauge board's, prony_creep.h, on the line's compliance), so the PAM's length is the
// tendon's minus that, and F solves F = pull(tendon - L0 - L0 (F + g q) / (E A)); a smooth
// friction's rate is then still the tendon's, not the muscle's (the line's stretch rate is
// left out of it).
// E A [N] of the actuator's line; 0 for an inextensible one.
double pam_line_axial_stiffness(const mjModel* m, int actuator_id);

// The actuator's AVBDL plant, or false if its plant is the spring law.
bool pam_plant_from_model(const mjModel* m, int actuator_id, AvbdlParams* plant);

// The spring model bound to actuator `id`.
SpringModel pam_spring_from_model(const mjModel* m, int actuator_id);
double pam_line_length(const mjModel* m, int actuator_id);
int pam_userdata_index(const mjModel* m, int actuator_id);

// The length [m] the line leaves the PAM: tendon length - line length (stretched by its
// tension, if extensible). While the line is taut it is the muscle's length; when slack it
// is shorter than the muscle, which then rests at its free length.
double pam_taut_length(const mjModel* m, const mjData* d, int actuator_id);
// The muscle's real length [m]: pam_taut_length while the line is taut, the free length when it
// is slack (a slack muscle is not pulled below its free length). What the encoder, the
// fiber sensor, the chamber volume and the error metrics see. A trial passes its muscle's
// `track` (avbdl.h), so a slack muscle's free length is searched from its last one.
double pam_muscle_length(const mjModel* m, const mjData* d, int actuator_id,
                         FreeLengthTrack* track = nullptr);
// The same, with the step's pam_taut_length already at hand (`taut` [m], which must be
// pam_taut_length(m, d, actuator_id) of this same state): an extensible line's length is a root
// solve, so a step that needs both solves it once.
double pam_muscle_length_at(const mjModel* m, const mjData* d, int actuator_id, double taut,
                            FreeLengthTrack* track = nullptr);

// Moves the actuator's history (Maxwell-slip elements, bladder relaxation) to the muscle's
// length at this step, its pam_muscle_length (call once after each physics step, with the
// data the step's forces were computed from); nothing for a plant without history
// (pam_has_history) or the spring law.
void pam_commit_history(const mjModel* m, mjData* d, int actuator_id, double muscle_length_m);

// The mjcb_act_bias callback: actuator force [N] (<= 0, a pull). PAM length
// l = tendon length - line length. The spring law: d = l - l_n(p), Eq. (1)-(5); AVBDL:
// Pipan et al.'s Eq. (25) plus friction at the tendon's velocity. The force pulls only (the
// actuator force is -f, f >= 0) and is zero when the PAM is slack or unbound.
mjtNum pam_actuator_force(const mjModel* m, const mjData* d, int actuator_id);

// Sets mjcb_act_bias once per process (called by install_mujoco_handlers).
void install_pam_actuator_callback();

}  // namespace pamsim
