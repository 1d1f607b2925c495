// scenario.h: a trial's complete description, read from a scenario TOML file plus
// `--set key=value` overrides, validated once. Keys (units in their names; SI except where
// the papers' units are named):
//   seed                      integer >= 0
//   model.file                MJCF of the arm                       (path, relative to the file)
//   model.agonist_params      PAM parameter file (models/pams/...)  (path)
//   model.antagonist_params   PAM parameter file                    (path)
//   model.calibration         line lengths from `pamsim calibrate`  (path)
//   model.pneumatics          valve and chamber parameters          (path)
//   sim.timestep_s            physics step, (0, 0.01], default 0.001
//   sim.duration_s            > 0, default 3
//   sim.control_hz            control and logging rate, default 100; timestep * rate <= 1
//   drop.enabled              default true
//   drop.mass_kg              (0, 10], default 0.2 (paper)
//   drop.height_m             ball bottom above basket floor, [0, 1], default 0.14 (paper)
//   drop.time_s               release time, [0, duration), default 1.0
//   pressure.agonist_MPa      goal pressure of the top controller, [0, supply]
//   pressure.antagonist_MPa
//   valve.model               "iso6358" | "first_order"
// Reflex and sensor keys (reflex.*, sensors.*) are read by the reflex controller's config.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "pam_actuator/pam_params.h"
#include "pam_actuator/pneumatics.h"
#include "reflex/reflex_controller.h"

namespace pamsim {

// The keys that hold file paths (relative to the scenario file): model.file and the
// other model.* files.
const std::vector<std::string>& scenario_path_keys();

struct Scenario {
  std::string path;   // the scenario file (for messages and summaries)

  std::string model_file;
  std::string agonist_params;
  std::string antagonist_params;
  std::string calibration_file;
  std::string pneumatics_file;

  std::uint64_t seed = 1;
  double timestep_s = 0.001;
  double duration_s = 3.0;
  double control_hz = 100.0;

  bool drop_enabled = true;
  double drop_mass_kg = 0.2;
  double drop_height_m = 0.14;
  double drop_time_s = 1.0;

  double p_goal_agonist_pa = 0.4e6;
  double p_goal_antagonist_pa = 0.4e6;
  ValveModel valve_model = ValveModel::kIso6358;
  PneumaticParams pneumatics;   // from model.pneumatics
  std::array<PamParams, kMuscleCount> pam;   // from model.agonist_params, antagonist_params

  // reflex and sensors; reflex.enabled = false gives the passive arm (top controller only)
  ReflexControllerConfig reflex;
};

// Reads and validates. Throws InputError "<file>: <key> <problem>" on the first error.
Scenario load_scenario(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from the scenario's text, as if read from `path` (relative paths resolve against
// its folder): a sweep runs every point on the base scenario it validated, even if the file
// changes on disk meanwhile.
Scenario load_scenario_text(const std::string& text, const std::string& path,
                            const std::vector<std::string>& overrides = {});

}  // namespace pamsim
