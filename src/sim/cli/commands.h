// commands.h: the `pamsim` subcommands. Each add_*_command registers one subcommand on
// the CLI11 app; its callback throws InputError on bad input, which main() turns into
// one line on stderr and a non-zero exit.
#pragma once

#include <stdexcept>
#include <string>

namespace CLI {
class App;
}

namespace pamsim {

void add_fit_command(CLI::App& app);         // fit a spring model to tensile data
void add_estimate_command(CLI::App& app);    // deformation and length from (p, f)
void add_tensile_command(CLI::App& app);     // virtual static tensile test
void add_calibrate_command(CLI::App& app);   // solve the arm's line lengths
void add_run_command(CLI::App& app);         // run a scenario (one or many trials)
void add_compare_command(CLI::App& app);     // two runs' angle bands and metrics side by side
void add_render_command(CLI::App& app);      // a trial as MP4/PNG video, headless
void add_sweep_command(CLI::App& app);       // run a parameter sweep into SQLite
void add_merge_command(CLI::App& app);       // merge a sweep's shard databases
void add_export_command(CLI::App& app);      // a sweep database as CSV
void add_report_command(CLI::App& app);      // per-point statistics, heat maps, best setting
void add_validate_command(CLI::App& app);    // the papers' validation experiments (Table III, V)
void add_tune_command(CLI::App& app);        // tune settings with CMA-ES / NSGA-II (pagmo2)
void add_identify_command(CLI::App& app);    // fit physical parameters to recordings (Ceres)
void add_keys_command(CLI::App& app);        // the scenario keys, documented
void add_replay_command(CLI::App& app);      // one trial of a sweep database, again, in full
void add_controller_command(CLI::App& app);  // the controller as embedded C: export, replay
void add_view_command(CLI::App& app);        // a trial live in a window (GLFW, MuJoCo's UI)
void add_hil_command(CLI::App& app);         // a controller board closing the loop (UDP, serial)

// A CLI11 check for a --seed bound to an unsigned integer, which CLI11 would otherwise wrap
// from a negative number: "" (valid) or the one-line problem.
inline std::string non_negative_seed(const std::string& text) {
  return !text.empty() && text[0] == '-' ? "must be >= 0, got " + text : std::string();
}

// Thrown by a command that has printed its own message and ends with `code` (e.g. 130 for
// an interrupted sweep).
class CommandExit : public std::runtime_error {
 public:
  explicit CommandExit(int code) : std::runtime_error("exit " + std::to_string(code)), code(code) {}
  int code;
};

}  // namespace pamsim
