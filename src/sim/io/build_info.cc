// build_info.cc: see build_info.h. PAMSIM_GIT_COMMIT comes from a header generated at every
// build (scripts/git-commit.cmake).
#include "sim/io/build_info.h"

#include <mujoco/mujoco.h>

#include "pneumatics/cvode_integrator.h"
#include "pamsim_git_commit.h"

namespace pamsim {

BuildInfo build_info() {
  BuildInfo b;
  b.pamsim_version = PAMSIM_VERSION;
  b.git_commit = PAMSIM_GIT_COMMIT;
  b.mujoco_version = mj_versionString();
  b.sundials_version = sundials_version();
#if defined(__clang__)
  b.compiler = std::string("Clang ") + __clang_version__;
#elif defined(__GNUC__)
  b.compiler = std::string("GCC ") + __VERSION__;
#else
  b.compiler = "unknown";
#endif
  return b;
}

nlohmann::json build_info_json() {
  const BuildInfo b = build_info();
  return {{"pamsim_version", b.pamsim_version},
          {"git_commit", b.git_commit},
          {"mujoco_version", b.mujoco_version},
          {"sundials_version", b.sundials_version},
          {"compiler", b.compiler}};
}

}  // namespace pamsim
