// main.cc: the `pamsim` command line. Subcommands live in cmd_*.cc (see commands.h);
// here only the dispatch and the one place that turns errors into an exit code.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <functional>
#include <cerrno>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "base/format.h"
#include "base/input_error.h"
#include "sim/cli/commands.h"
#include "sim/io/provenance.h"
#include "base/suggest.h"

namespace {

// A missing or unknown subcommand of the deepest command given: the word given (empty when
// none was) and "; commands: a, b, c" (and "; did you mean b?"); both empty otherwise.
struct SubcommandProblem {
  std::string unknown;
  std::string hint;
};

SubcommandProblem subcommand_problem(const CLI::App& app, int argc, char** argv) {
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
  if (subs.empty()) return {};
  const bool missing = next >= argc;
  const bool unknown = !missing && argv[next][0] != '-';
  if (!missing && !unknown) return {};
  std::string list;
  std::vector<std::string> names;
  for (const CLI::App* s : subs) {
    list += (list.empty() ? "" : ", ") + s->get_name();
    names.push_back(s->get_name());
  }
  SubcommandProblem problem{unknown ? argv[next] : "", "; commands: " + list};
  const std::string nearest = unknown ? pamsim::nearest_name(argv[next], names) : "";
  if (!nearest.empty()) problem.hint += "; did you mean " + nearest + "?";
  return problem;
}

// "--trials must be a whole number >= 0, got 2.5" for CLI11's "Could not convert: --trials =
// 2.5", from the option's type; CLI11's own text for anything else.
std::string conversion_message(const CLI::App& app, const std::string& what) {
  const std::string head = "Could not convert: ";
  const std::size_t eq = what.find(" = ");
  if (what.rfind(head, 0) != 0 || eq == std::string::npos) return what;
  const std::string name = what.substr(head.size(), eq - head.size());
  const std::string value = what.substr(eq + 3);
  const CLI::App* at = &app;
  for (const CLI::App* sub : app.get_subcommands()) at = sub;  // the command given
  const CLI::Option* opt = at->get_option_no_throw(name);
  const std::string type = opt ? opt->get_type_name() : "";
  const std::string wanted = type == "UINT"    ? "a whole number >= 0"
                             : type == "INT"   ? "a whole number"
                             : type == "FLOAT" ? "a number"
                                               : "a value of type " + type;
  return type.empty() ? what : name + " must be " + wanted + ", got " + value;
}

// The one line a usage error is told in: an unknown command by name (CLI11 says "A
// subcommand is required" for it), a value by its option's type.
std::string usage_message(const CLI::App& app, const CLI::ParseError& e, int argc, char** argv) {
  const SubcommandProblem problem = subcommand_problem(app, argc, argv);
  if (!problem.unknown.empty()) return "unknown command '" + problem.unknown + "'" + problem.hint;
  return conversion_message(app, e.what()) + problem.hint;
}

}  // namespace

int main(int argc, char** argv) {
  pamsim::record_command_line(argc, argv);
  CLI::App app{"pamsim: simulation testbed for PAM-driven arms with a stretch reflex"};
  app.set_version_flag("--version", std::string("pamsim ") + PAMSIM_VERSION);
  app.require_subcommand(1);
  app.option_defaults()->always_capture_default();  // --help shows every option's default

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
  pamsim::add_controller_command(app);
  pamsim::add_view_command(app);
  pamsim::add_hil_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // one line, like every other input error (CLI11's own exit adds a second one), exit 2
    // (CLI11's own codes, 104-109, are not pamsim's); a missing or unknown subcommand is
    // answered with the ones there are, and the nearest name
    std::cerr << "pamsim: " << pamsim::printable_message(usage_message(app, e, argc, argv)) << "\n";
    return 2;
  } catch (const pamsim::CommandExit& e) {
    return e.code;
  } catch (const pamsim::SimulationFailed&) {
    return 4;
  } catch (const pamsim::InputError& e) {
    std::cerr << "pamsim: " << pamsim::printable_message(e.what()) << "\n";
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    // a path the user gave that cannot be one (too long, through a file, not allowed): bad
    // input, in one line naming the path; anything else the file system says is an error
    const int code = e.code().value();
    const bool input =
        code == ENAMETOOLONG || code == ENOTDIR || code == EACCES || code == EROFS || code == ELOOP;
    std::cerr << "pamsim: " << (input ? "" : "error: ")
              << pamsim::printable_message(e.path1().string() + ": " + e.code().message()) << "\n";
    return input ? 2 : 1;
  } catch (const std::exception& e) {
    std::cerr << "pamsim: error: " << pamsim::printable_message(e.what()) << "\n";
    return 1;
  }
  return 0;
}
