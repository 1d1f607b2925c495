// muscle_binding.h: each PAM actuator's law and the place of its state, bound to its model
// once and read by the force callback (pam_callback.h). The one table that says what a
// muscle is to the physics: the spring law of Eq. (1)-(5) that its estimator inverts, the
// plant's AVBDL law (Pipan et al., Eq. (25), with friction, its bladder and relaxation: avbdl.h)
// with its shape derived once here, the line, and where in d->userdata the trial keeps the
// muscle's chamber pressure and history. A plant feature is a field of AvbdlParams and is
// bound with it; nothing is packed into the model's actuator_user slots.
#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>
#include <memory>

#include "pam_actuator/avbdl.h"
#include "pam_actuator/spring_model.h"

namespace pamsim {

// A muscle's line beyond its length: a spring in series with it (E A), and its creep, one
// Kelvin-Voigt element on that spring's compliance (pam_callback.h).
struct LineBinding {
  double axial_stiffness_n = 0.0;  // E A [N]; 0: inextensible
  double creep = 0.0;              // g >= 0: the long-term creep per unit elastic stretch
  double creep_time_s = 0.0;       // tau > 0: its retardation time
  double start_tension_n = 0.0;    // F0, held long before the trial: the creep state's start
  int creep_index = -1;            // d->userdata index of the creep state q [N], or -1
};

struct MuscleBinding {
  SpringModel spring;          // Eq. (1)-(5): the estimator's law; the plant's too
                               // when has_plant is false
  double line_length_m = 0.0;  // the line's unstretched length
  LineBinding line;            // its stretch and creep
  int pressure_index = -1;     // d->userdata index of the chamber gauge pressure [Pa]
  bool has_plant = false;      // else the spring law is the plant
  AvbdlParams plant;           // the plant's law, when has_plant
  int slip_block = -1;         // d->userdata index of [L_prev, s_1..s_N] (Maxwell-slip), or -1
  int relaxation_block = -1;   // ... of [L_prev, F_e(L_prev), h_1..h_N] (relaxation), or -1
};

// A binding with what its plant derives from its parameters alone, computed when bound.
struct BoundMuscleLaw {
  MuscleBinding binding;
  AvbdlShape shape;           // avbdl_shape(binding.plant), when has_plant
  double max_length_m = 0.0;  // avbdl_max_length(binding.plant), when has_plant
};

// The table is keyed by the model's address: load_trial_model binds a model's muscles,
// copy_model (mujoco_util.h) gives a copy the same bindings, and MjModelPtr's deleter
// unbinds them, so a model deleted and another allocated at its address find nothing stale.
// Trials on other threads share a model's bindings read-only; everything that changes
// during a trial lives in its mjData. (The binding is what a MuJoCo >= 2.3 actuator plugin
// would hold as its instance's configuration, and the userdata blocks its plugin state.)
//
// Binds actuator `actuator_id` of `m` (replacing any binding it had).
void bind_muscle(const mjModel* m, int actuator_id, const MuscleBinding& binding);
// Actuator `actuator_id`'s binding, or nullptr if it has none.
std::shared_ptr<const BoundMuscleLaw> find_muscle(const mjModel* m, int actuator_id);
// Gives `to` the bindings of `from` (mj_copyModel copies the model, not its bindings).
void copy_muscle_bindings(const mjModel* from, const mjModel* to);
// Forgets every binding of `m` (before it is deleted).
void unbind_muscles(const mjModel* m);
// Changes whenever a binding is made, copied or forgotten: a reader that keeps copies of
// bindings (the force callback's per-thread ones) drops them when it changes.
std::uint64_t muscle_binding_epoch();

// The userdata a PAM's history takes: its Maxwell-slip block (L_prev and one state per
// element) and its relaxation block (above), each only when used.
int pam_history_size(const AvbdlParams& plant);
bool pam_has_history(const AvbdlParams& plant);

// Binds actuator `id`'s spring law, line and chamber pressure (d->userdata[userdata_index]);
// an AVBDL plant bound before stays. Throws InputError naming `path` (the model file) if the
// actuator is not a general actuator on a tendon with biastype="user", or the model's
// nuserdata cannot hold the pressure.
void store_pam_in_model(const mjModel* m, int actuator_id, const SpringModel& spring,
                        double line_length_m, int userdata_index, const char* path);
// Makes actuator `id`'s plant the AVBDL law (the spring law stays the estimator's and the
// calibration's); its history (a Maxwell-slip friction's state, then the bladder's
// relaxation) takes pam_history_size values of d->userdata from `history_index` on. Throws
// InputError if the model's nuserdata cannot hold that history, or the actuator is unbound.
void store_plant_in_model(const mjModel* m, int actuator_id, const AvbdlParams& plant,
                          int history_index, const char* path);
// Makes actuator `id`'s line extensible with axial stiffness E A = line.axial_stiffness_n > 0
// (inextensible for 0), creeping when line.creep > 0 (its state d->userdata[creep_index]).
// Throws InputError if the actuator is unbound or the model's nuserdata cannot hold the state.
void store_line_in_model(const mjModel* m, int actuator_id, const LineBinding& line,
                         const char* path);

}  // namespace pamsim
