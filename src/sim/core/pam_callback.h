// pam_callback.h: the MuJoCo binding of the PAM force law (Eq. (1)-(5)).
//
// MuJoCo 2.2.2 has no plugins: each PAM is a `general` actuator on its tendon with
// biastype="user"; the process-global mjcb_act_bias calls pam_actuator_force, a pure
// function of (m, d, id). Everything it needs is in the model or the trial's data:
//   m->actuator_user[id * nuser_actuator + k], k = 0..10 (written by store_pam_in_model):
//     0 law (0 eq3, 1 eq4, 2 eq5), 1 m [m/Pa], 2 h [m], 3..8 SI coefficients,
//     9 line length [m], 10 index into d->userdata of this PAM's chamber gauge pressure [Pa]
//   and, in models with nuser_actuator >= kPamPlantUserSize (written by store_plant_in_model),
//     11 the plant law: 0 the spring law above (plant = estimator), 1 AVBDL (avbdl.h);
//     12..27 the AVBDL parameters, SI: L0, D0, alpha0, wall, C10, C01, C20, Ld, a, v_s,
//     extension F0, A0, A1, contraction F0, A0, A1;
//   and, in models with nuser_actuator >= kPamSlipUserSize, the friction's form:
//     28 0 smooth, 1 Maxwell-slip; 29 its element count N; 30..33 weights; 34..37
//     breakaway travels [m]; 38 index into d->userdata of this PAM's slip block
//     [L_prev, s_1..s_N]: the muscle length at the last committed step (0: none yet, as
//     mj_resetData leaves it) and the elements' states (maxwell_slip.h).
//   and, in models with nuser_actuator >= kPamLineUserSize, 39 the line's axial stiffness
//   E A [N] (0: inextensible). An extensible line of unstretched length L0 (slot 9) and
//   tension F is L0 (1 + F / (E A)) long, so the PAM's length is the tendon's minus that,
//   and F solves F = pull(tendon - L0 - L0 F / (E A)) (issue 25, item 3); a smooth
//   friction's rate is then still the tendon's, not the muscle's (the line's stretch rate
//   is left out of it).
//   and, in models with nuser_actuator >= kPamBladderUserSize, the bladder's form (avbdl.h):
//     40 its law (0 Mooney-Rivlin, slots 16..18; 1 Gent-Gent), 41 its tube's diameter Db [m]
//     (0: the braid's), 42..44 Gent-Gent mu [Pa], C2 [Pa], Jm.
//   and, in models with nuser_actuator >= kPamRelaxationUserSize, the bladder's rate term
//   (bladder_relaxation.h): 45 its term count N (0: none), 46..49 weights g_i, 50..53
//   times tau_i [s], 54 index into d->userdata of this PAM's relaxation block
//   [L_prev, F_e(L_prev), h_1..h_N]: the committed length (0: none yet), the bladder's relaxed
//   force there [N] and the terms' overstresses [N].
// The Maxwell-slip and relaxation states move only at pam_commit_history, once per physics
// step; the callback evaluates them as they would be at the step's length, without storing.
// The overstress adds to a taut muscle's pull (a slack one pulls nothing).
// PAM length l = tendon length - line length. The spring law: d = l - l_n(p), Eq. (1)-(5);
// AVBDL: seeds/003 Eq. (25) plus friction at the tendon's velocity. The force pulls only
// (the actuator force is -f, f >= 0) and is zero when the PAM is slack.
#pragma once

#include <mujoco/mujoco.h>

#include "pam_actuator/avbdl.h"
#include "pam_actuator/spring_model.h"

namespace pamsim {

inline constexpr int kPamUserSize = 11;
inline constexpr int kPamPlantUserSize = 28;
inline constexpr int kPamSlipUserSize = kPamPlantUserSize + 3 + 2 * kMaxSlipElements;

inline constexpr int kPamLineUserSize = kPamSlipUserSize + 1;
inline constexpr int kPamBladderUserSize = kPamLineUserSize + 5;
inline constexpr int kPamRelaxationUserSize = kPamBladderUserSize + 2 + 2 * kMaxRelaxationTerms;

// The userdata a PAM's history takes: its Maxwell-slip block (L_prev and one state per
// element) and its relaxation block (above), each only when used.
int pam_history_size(const AvbdlParams& plant);

// Writes the PAM's parameters into actuator `id`'s user slots. Throws InputError if the
// model declares nuser_actuator < kPamUserSize or the actuator is not a user-bias tendon
// actuator; `path` names the model file in the message.
void store_pam_in_model(mjModel* m, int actuator_id, const SpringModel& spring,
                        double line_length_m, int userdata_index, const char* path);

// Makes actuator `id`'s plant the AVBDL law (the spring law stays the estimator's and the
// calibration's); its history (a Maxwell-slip friction's state, then the bladder's
// relaxation) takes pam_history_size values of d->userdata from index `history_index` on.
// Throws InputError if the model declares nuser_actuator < kPamPlantUserSize, or, for a
// Maxwell-slip friction, nuser_actuator < kPamSlipUserSize, for a tube bladder or the
// Gent-Gent law, nuser_actuator < kPamBladderUserSize, for a relaxing bladder,
// nuser_actuator < kPamRelaxationUserSize, or too small a nuserdata for the history.
void store_plant_in_model(mjModel* m, int actuator_id, const AvbdlParams& plant,
                          int history_index, const char* path);
// Makes actuator `id`'s line extensible with axial stiffness E A = axial_stiffness_n > 0, or
// inextensible for 0. Throws InputError if an extensible line finds nuser_actuator <
// kPamLineUserSize.
void store_line_stiffness_in_model(mjModel* m, int actuator_id, double axial_stiffness_n,
                                   const char* path);
// E A [N] of the actuator's line; 0 for an inextensible one.
double pam_line_axial_stiffness(const mjModel* m, int actuator_id);

// The actuator's AVBDL plant, or false if its plant is the spring law.
bool pam_plant_from_model(const mjModel* m, int actuator_id, AvbdlParams* plant);

// The spring model stored in actuator `id`'s user slots.
SpringModel pam_spring_from_model(const mjModel* m, int actuator_id);
double pam_line_length(const mjModel* m, int actuator_id);
int pam_userdata_index(const mjModel* m, int actuator_id);

// The length [m] the line leaves the PAM: tendon length - line length (stretched by its
// tension, if extensible). While the line is taut it is the muscle's length; when slack it
// is shorter than the muscle, which then rests at its free length.
double pam_length(const mjModel* m, const mjData* d, int actuator_id);
// The muscle's real length [m]: pam_length while the line is taut, the free length when it
// is slack (a slack muscle is not pulled below its free length). What the encoder, the
// fiber sensor, the chamber volume and the error metrics see. A trial passes its muscle's
// `track` (avbdl.h), so a slack muscle's free length is searched from its last one.
double pam_muscle_length(const mjModel* m, const mjData* d, int actuator_id,
                         FreeLengthTrack* track = nullptr);
// The same, with the step's pam_length already at hand (`taut` [m], which must be
// pam_length(m, d, actuator_id) of this same state): an extensible line's length is a root
// solve, so a step that needs both solves it once.
double pam_muscle_length_at(const mjModel* m, const mjData* d, int actuator_id, double taut,
                            FreeLengthTrack* track = nullptr);

// Moves the actuator's history (Maxwell-slip elements, bladder relaxation) to the muscle's
// length at this step, its pam_muscle_length (call once after each physics step, with the
// data the step's forces were computed from); nothing for a plant without history
// (pam_has_history) or the spring law.
void pam_commit_history(const mjModel* m, mjData* d, int actuator_id, double muscle_length_m);
bool pam_has_history(const AvbdlParams& plant);

// The mjcb_act_bias callback: actuator force [N] (<= 0, a pull).
mjtNum pam_actuator_force(const mjModel* m, const mjData* d, int actuator_id);

// Sets mjcb_act_bias once per process (called by install_mujoco_handlers).
void install_pam_actuator_callback();

}  // namespace pamsim
