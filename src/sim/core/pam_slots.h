// pam_slots.h: where a PAM's parameters and history live in a MuJoCo model and its trial's
// data (the actuator_user layout that pam_callback.h describes), shared by the slots'
// writer and reader (pam_slots.cc) and the force callback (pam_callback.cc). Internal to
// sim/core.
#pragma once

#include <mujoco/mujoco.h>

#include "pam_actuator/avbdl.h"

namespace pamsim::pam_slots {

// Throws "<path>: <size nuser_actuator> must be >= <slots> for <what>, got <n>" if the
// model's actuators have fewer user slots than `what` needs.
void require_user_slots(const mjModel* m, int slots, const char* what, const char* path);
// actuator `id`'s user slots
const mjtNum* user_slots(const mjModel* m, int id);
// the index in d->userdata of the actuator's slip block [L_prev, s_1..s_N]
int slip_block(const mjModel* m, int id);
// ... and of its relaxation block [L_prev, F_e(L_prev), h_1..h_N]
int relaxation_block(const mjModel* m, int id);
// the userdata a Maxwell-slip friction's block takes (0 for a smooth friction)
int slip_block_size(const AvbdlParams& plant);

}  // namespace pamsim::pam_slots
