// main.cc: the `pamsim` command line. Subcommands live in cmd_*.cc (see commands.h);
// here only the dispatch and the one place that turns errors into an exit code.
#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>

#include "pam_actuator/input_error.h"
#include "sim/cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"pamsim: simulation testbed for PAM-driven arms with a stretch reflex"};
  app.set_version_flag("--version", std::string("pamsim ") + PAMSIM_VERSION);
  app.require_subcommand(1);

  pamsim::add_fit_command(app);
  pamsim::add_estimate_command(app);
  pamsim::add_tensile_command(app);
  pamsim::add_calibrate_command(app);
  pamsim::add_run_command(app);
  pamsim::add_compare_command(app);
  pamsim::add_render_command(app);
  pamsim::add_sweep_command(app);
  pamsim::add_export_command(app);
  pamsim::add_report_command(app);
  pamsim::add_validate_command(app);
  pamsim::add_tune_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {   // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // one line, like every other input error (CLI11's own exit adds a second one)
    std::cerr << "pamsim: " << e.what() << "\n";
    return e.get_exit_code() != 0 ? e.get_exit_code() : 2;
  } catch (const pamsim::CommandExit& e) {
    return e.code;
  } catch (const pamsim::SimulationFailed&) {
    return 4;
  } catch (const pamsim::InputError& e) {
    std::cerr << "pamsim: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "pamsim: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
