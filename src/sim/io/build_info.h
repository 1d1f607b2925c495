// build_info.h: what built this pamsim (its version and git commit, the MuJoCo and SUNDIALS
// it runs with, the compiler), for the provenance every output records (provenance.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace pamsim {

struct BuildInfo {
  std::string pamsim_version;    // PROJECT_VERSION, "0.3.0"
  std::string git_commit;        // the source tree's commit, "+dirty" if changed, or "unknown"
  std::string mujoco_version;    // as the library reports it at run time (mj_versionString)
  std::string sundials_version;  // likewise (SUNDIALSGetVersion)
  std::string compiler;          // "GCC 12.2.0"
};

BuildInfo build_info();
// {"pamsim_version", "git_commit", "mujoco_version", "sundials_version", "compiler"}
nlohmann::json build_info_json();

}  // namespace pamsim
