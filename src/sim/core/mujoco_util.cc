// mujoco_util.cc: see mujoco_util.h.
#include "sim/core/mujoco_util.h"

#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>

#include "base/input_error.h"
#include "sim/core/pam_callback.h"

namespace pamsim {
namespace {

void on_mujoco_error(const char* msg) {
  std::fprintf(stderr, "pamsim: MuJoCo error: %s\n", msg);
  std::exit(3);
}

void on_mujoco_warning(const char* msg) {
  // instabilities are also counted in mjData::warning and end the trial as "diverged"
  std::fprintf(stderr, "pamsim: MuJoCo warning: %s\n", msg);
}

}  // namespace

void install_mujoco_handlers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mju_user_error = on_mujoco_error;
    mju_user_warning = on_mujoco_warning;
    install_pam_actuator_callback();
  });
}

MjModelPtr load_mjcf(const std::string& path) {
  install_mujoco_handlers();
  char error[1024] = "";
  mjModel* m = mj_loadXML(path.c_str(), nullptr, error, sizeof(error));
  if (!m) {
    std::string why = error[0] ? error : "unknown error";
    for (char& c : why) {
      if (c == '\n') c = ' ';
    }
    throw InputError(path + ": model failed to load: " + why);
  }
  return MjModelPtr(m);
}

void MjModelDeleter::operator()(mjModel* m) const {
  unbind_muscles(m);
  mj_deleteModel(m);
}

MjModelPtr copy_model(const mjModel* m) {
  MjModelPtr copy(mj_copyModel(nullptr, m));
  if (!copy) throw std::runtime_error("mj_copyModel failed");
  copy_muscle_bindings(m, copy.get());
  return copy;
}

MjDataPtr make_data(const mjModel* m) {
  mjData* d = mj_makeData(m);
  if (!d) throw std::runtime_error("mj_makeData failed");
  return MjDataPtr(d);
}

int require_id(const mjModel* m, mjtObj type, const std::string& name, const std::string& path) {
  const int id = mj_name2id(m, type, name.c_str());
  if (id < 0) {
    throw InputError(path + ": model has no " + mju_type2Str(type) + " named '" + name + "'");
  }
  return id;
}

}  // namespace pamsim
