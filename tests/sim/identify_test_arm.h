// identify_test_arm.h: the recordings the identification tests fit, made by pamsim from the
// example arm (examples/identify/arm.toml) whose antagonist's wall is 2.7 mm where the model
// says 3.0: its angle at 50 Hz over 2 s, noise seed 7, under a command schedule.
#pragma once

#include <filesystem>
#include <string>

#include "base/format.h"
#include "cli_util.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/scenario/scenario_file.h"

namespace pamsim {

inline const std::string kArm = std::string(PAMSIM_SOURCE_DIR) + "/examples/identify/arm.toml";
inline const std::string kSteps =
    "muscles.agonist.command={kind=\"steps\", times_s=[0.0, 1.0], MPa=[0.3, 0.5]}";
inline const std::string kSine =
    "muscles.antagonist.command={kind=\"sine\", offset_MPa=0.4, amplitude_MPa=0.15, period_s=1.5}";

// The true arm's angle under `command` as a recording in `file`, read `delay_rows` 10 ms
// log rows late (an unmodelled sensor delay; 0: none).
inline void record_arm(const std::filesystem::path& file, const std::string& command,
                       std::size_t delay_rows = 0) {
  const Scenario sc =
      load_scenario(kArm, {"muscles.antagonist.plant.geometry.wall_thickness_mm=2.7",
                           "sim.duration_s=2", "seed=7", command});
  const TrialResult t = run_trial(load_trial_model(sc), sc, sc.seed, true);
  std::string csv = "time_s,angle_deg\n";
  const std::size_t angle = t.trajectory.column("angle_deg");
  for (std::size_t row = 0; row < t.trajectory.rows(); row += 2) {
    const std::size_t seen = row >= delay_rows ? row - delay_rows : 0;
    csv += format_shortest(t.trajectory.at(row, 0)) + "," +
           format_shortest(t.trajectory.at(seen, angle)) + "\n";
  }
  pamsim_test::write_text(file, csv);
}

}  // namespace pamsim
