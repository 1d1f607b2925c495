// main.cc: the `pamsim` command line. Subcommands live in cmd_*.cc (see commands.h);
// here only the dispatch and the one place that turns errors into an exit code.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/input_error.h"
#include "sim/cli/commands.h"
#include "sim/io/provenance.h"
#include "base/suggest.h"

namespace {

// "; commands: a, b, c" (and "; did you mean b?") for the deepest command given whose
// subcommand is missing or unknown; "" otherwise.
std::string subcommand_hint(const CLI::App& app, int argc, char** argv) {
  const CLI::App* at = &app;
  int next = 1;
  // walk the subcommands the arguments name
  while (next < argc) {
    const CLI::App* sub = nullptr;
    for (const CLI::App* s : at->get_subcommands(std::function<bool(const CLI::App*)>{})) {
      if (s->get_name() == argv[next]) sub = s;
    }
    if (!sub) break;
    at = sub;
    ++next;
  }
  const std::vector<const CLI::App*> subs =
      at->get_subcommands(std::function<bool(const CLI::App*)>{});
  if (subs.empty()) return "";
  const bool missing = next >= argc;
  const bool unknown = !missing && argv[next][0] != '-';
  if (!missing && !unknown) return "";
  std::string list;
  std::vector<std::string> names;
  for (const CLI::App* s : subs) {
    list += (list.empty() ? "" : ", ") + s->get_name();
    names.push_back(s->get_name());
  }
  std::string hint = "; commands: " + list;
  const std::string nearest = unknown ? pamsim::nearest_name(argv[next], names) : "";
  if (!nearest.empty()) hint += "; did you mean " + nearest + "?";
  return hint;
}

}  // namespace

int main(int argc, char** argv) {
  pamsim::record_command_line(argc, argv);
  CLI::App app{"pamsim: simulation testbed for PAM-driven arms with a stretch reflex"};
  app.set_version_flag("--version", std::string("pamsim ") + PAMSIM_VERSION);
  app.require_subcommand(1);
  app.option_defaults()->always_capture_default();   // --help shows every option's default

  pamsim::add_fit_command(app);
  pamsim::add_estimate_command(app);
  pamsim::add_tensile_command(app);
  pamsim::add_calibrate_command(app);
  pamsim::add_run_command(app);
  pamsim::add_compare_command(app);
  pamsim::add_render_command(app);
  pamsim::add_sweep_command(app);
  pamsim::add_merge_command(app);
  pamsim::add_export_command(app);
  pamsim::add_report_command(app);
  pamsim::add_validate_command(app);
  pamsim::add_tune_command(app);
  pamsim::add_identify_command(app);
  pamsim::add_keys_command(app);
  pamsim::add_replay_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // one line, like every other input error (CLI11's own exit adds a second one), exit 2
    // (CLI11's own codes, 104-109, are not pamsim's); a missing or unknown subcommand is
    // answered with the ones there are, and the nearest name
    std::cerr << "pamsim: "
              << pamsim::printable_message(e.what() + subcommand_hint(app, argc, argv)) << "\n";
    return 2;
  } catch (const pamsim::CommandExit& e) {
    return e.code;
  } catch (const pamsim::SimulationFailed&) {
    return 4;
  } catch (const pamsim::InputError& e) {
    std::cerr << "pamsim: " << pamsim::printable_message(e.what()) << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "pamsim: error: " << pamsim::printable_message(e.what()) << "\n";
    return 1;
  }
  return 0;
}
