// mujoco_util.h: owning handles for mjModel/mjData (a model's handle also owns its muscle
// bindings), the process-wide MuJoCo error and warning handlers (so a batch run never waits
// on stdin), and model loading that turns
// MuJoCo's error buffer into an InputError naming the file.
#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <string>

namespace pamsim {

// Forgets the model's muscle bindings (muscle_binding.h), then deletes it.
struct MjModelDeleter {
  void operator()(mjModel* m) const;
};
struct MjDataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using MjModelPtr = std::unique_ptr<mjModel, MjModelDeleter>;
using MjDataPtr = std::unique_ptr<mjData, MjDataDeleter>;

// Installs mju_user_error / mju_user_warning and the PAM actuator callback, once per
// process (idempotent, thread-safe). Errors print one line and exit(3): MuJoCo's C code
// cannot be unwound by an exception. Warnings are counted in mjData and checked by the loop.
void install_mujoco_handlers();

// Loads an MJCF file. Throws InputError "<path>: <MuJoCo's message>" if it fails.
MjModelPtr load_mjcf(const std::string& path);

MjDataPtr make_data(const mjModel* m);

// A copy of `m` (mj_copyModel) with the same muscle bindings.
MjModelPtr copy_model(const mjModel* m);

// Id of a named object or InputError "<path>: model has no <what> named '<name>'".
int require_id(const mjModel* m, mjtObj type, const std::string& name, const std::string& path);

}  // namespace pamsim
