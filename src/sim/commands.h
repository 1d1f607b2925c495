// commands.h: the `pamsim` subcommands. Each add_*_command registers one subcommand on
// the CLI11 app; its callback throws InputError on bad input, which main() turns into
// one line on stderr and a non-zero exit.
#pragma once

namespace CLI {
class App;
}

namespace pamsim {

void add_fit_command(CLI::App& app);        // fit a spring model to tensile data
void add_estimate_command(CLI::App& app);   // deformation and length from (p, f)
void add_tensile_command(CLI::App& app);    // virtual static tensile test
void add_calibrate_command(CLI::App& app);  // solve the arm's line lengths
void add_run_command(CLI::App& app);        // run a scenario (one or many trials)
void add_compare_command(CLI::App& app);    // two runs' angle bands and metrics side by side

}  // namespace pamsim
