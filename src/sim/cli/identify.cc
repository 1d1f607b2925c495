// identify.cc: `pamsim identify FILE.toml [--db FILE] [--out DIR] [--threads N] [--resume]`:
// fits an identification file's parameters to its recordings
// (src/sim/optimize/identify.h), every simulated point stored in SQLite as it is computed,
// then writes identified.toml, identify.csv, identify_fits.csv and identify.md. Everything is
// validated before the database is created; a killed run keeps every point; --resume replays
// the search with them and goes on.
#include "sim/optimize/identify_outputs.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>
#include <optional>
#include <string>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "sim/cli/command_database.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/cli/stop_signal.h"
#include "sim/core/runner.h"
#include "sim/io/plot.h"
#include "sim/io/staged_outputs.h"
#include "sim/optimize/identify_plan.h"

namespace pamsim {
namespace {

struct IdentifyOptions {
  std::string file;
  DatabaseOptions database;
  bool force = false;
  bool quiet = false;
  bool no_plot = false;
  bool plan = false;
  std::string plot_format = "png";
};

// The values, the channels' fits and, with --plan, the candidates ranked.
void print_result(const IdentifyResult& r, const std::optional<IdentifyPlan>& plan) {
  if (r.parameters.empty()) {
    std::cout << "the model held against the recordings (cost " << format_value(r.cost_final)
              << ", no parameter fitted):\n";
  } else {
    std::cout << "identified (cost " << format_value(r.cost_global) << " after CMA-ES, "
              << format_value(r.cost_final) << " after the polish):\n";
  }
  for (const IdentifiedParameter& p : r.parameters) {
    std::cout << "  " << p.parameter.key << " = ";
    if (!p.identifiable) {
      std::cout << format_value(p.value) << "  (not determined by the recordings)\n";
      continue;
    }
    std::cout << format_with_error(p.value, p.std_error) << ", "
              << format_value(100.0 * r.interval_level) << " % in [" << format_value(p.interval_lo)
              << ", " << format_value(p.interval_hi) << "]" << (p.at_bound ? "  (at a bound)" : "")
              << "\n";
  }
  for (const ChannelFit& f : r.fits) {
    std::cout << "  " << f.recording << " " << f.channel << (f.held_out ? " (held out)" : "")
              << ": RMSE ";
    if (!r.parameters.empty()) std::cout << format_value(f.rmse_before) << " -> ";
    std::cout << format_value(f.rmse_after);
    if (std::isfinite(f.noise_floor)) std::cout << " (noise " << format_value(f.noise_floor) << ")";
    if (r.parameters.empty() && f.judged)
      std::cout << (f.explained ? ", explained" : ", NOT explained");
    std::cout << "\n";
  }
  if (!plan) return;
  std::cout << "plan (plan.md):\n";
  for (const std::string& line : plan_lines(*plan)) std::cout << "  " << line << "\n";
}

// The outputs into `out`, staged then published together; the plan's with one.
void publish_outputs(const IdentifyDefinition& def, const IdentifyResult& r, const std::string& out,
                     bool plots, const std::optional<IdentifyPlan>& plan) {
  StagedOutputs staged(out, kIdentifyOutputs);
  staged.write([&] {
    write_identify_outputs(def, r, staged, plots);
    if (!plan) return;
    write_file_atomically(staged.path("plan.csv"), plan_csv(*plan));
    write_file_atomically(staged.path("plan.md"), plan_markdown(*plan));
  });
  staged.publish();
}

// what the run cost, where its outputs are, how the search ended, and the warnings, last
void print_ending(const IdentifyDefinition& def, const IdentifyResult& r, const std::string& out,
                  bool plots) {
  const bool fitted = !def.parameters.empty();
  std::cerr << "pamsim identify: " << r.simulated << " points simulated, " << r.cached
            << " from the database; "
            << (fitted ? format_value(r.global_s) + " s CMA-ES, " + format_value(r.polish_s) +
                             " s polish, "
                       : "")
            << format_value(r.check_s) << " s checks\n";
  std::cout << "outputs: " << out << "/{identified.toml,identify.csv,identify_fits.csv,identify.md"
            << (plots ? ",recording_*.png" : "") << "}"
            << (fitted ? " and the identified plant/pneumatics files" : "") << "\n";
  // the search's budget and how it ended, then what a user must not miss, last
  if (!fitted) {
    for (const std::string& line : identify_warnings(def, r))
      std::cout << "warning: " << line << "\n";
    return;
  }
  std::cout << "search: CMA-ES " << global_search_text(def, r) << " (cost "
            << format_value(r.cost_global) << "), then " << r.polish_iterations
            << " Levenberg-Marquardt iterations of at most " << def.polish_iterations << " ("
            << (r.polish_failed      ? "failed"
                : r.polish_converged ? "converged"
                                     : "not converged")
            << ", cost " << format_value(r.cost_final) << ")\n";
  for (const std::string& line : identify_warnings(def, r))
    std::cout << "warning: " << line << "\n";
}

// what will run, on how many threads, into which database
void print_start(const IdentifyDefinition& def, int threads, const std::string& db_path,
                 std::size_t stored) {
  const std::string on = std::to_string(threads) + (threads == 1 ? " thread" : " threads");
  if (def.parameters.empty()) {
    std::cerr << "pamsim identify: no [[parameter]]: the model held against "
              << def.recordings.size() << " recordings, on " << on << "\n";
    return;
  }
  std::cerr << "pamsim identify: " << def.parameters.size() << " parameters, "
            << def.recordings.size() << " recordings; CMA-ES "
            << (def.runs > 1 ? std::to_string(def.runs) + " runs of up to " : "") << def.generations
            << " generations of " << def.population << (def.runs > 1 ? " (doubling each run)" : "")
            << ", then up to " << def.polish_iterations
            << " Levenberg-Marquardt iterations per start, on " << on << " into " << db_path << " ("
            << stored << " points stored)\n";
}

void identify(const IdentifyOptions& opt) {
  const int threads = resolve_thread_count(opt.database.threads);
  const IdentifyDefinition def = load_identify_definition(opt.file);  // everything validated
  if (opt.plan && def.candidates.empty()) {
    throw InputError(opt.file +
                     ": --plan ranks the file's [[candidate]] experiments, and it has none");
  }
  if (opt.plan && def.parameters.empty()) {
    throw InputError(opt.file +
                     ": --plan ranks experiments by the parameters' uncertainty, "
                     "and the file has no [[parameter]]");
  }
  const CommandDatabase where = command_database(opt.file, opt.database, "identify.db");
  if (opt.database.resume && !where.exists) {
    throw InputError(where.path + ": --resume, but there is no database");
  }
  if (!opt.database.resume && !where.exists && !opt.force) {
    refuse_earlier_outputs(where.out, kIdentifyOutputs);
  }
  use_plot_formats(opt.plot_format);
  const bool plots = plots_wanted(opt.no_plot);
  IdentifyDb db = open_in_database_folder(where, "identify.db", [&] {
    return opt.database.resume ? IdentifyDb::open_to_resume(where.path, def)
                               : IdentifyDb::create(where.path, def);
  });
  print_start(def, threads, where.path, db.size());
  StopOnSignal stop_on_signal;
  IdentifyRunOptions run;
  run.threads = threads;
  run.stop = &stop_requested();
  if (!opt.quiet) {
    run.on_progress = [](const std::string& phase, std::int64_t points) {
      if (points % 10 == 0)
        std::cerr << "pamsim identify: " << phase << " " << points << " points\n";
    };
  }
  const IdentifyResult r = run_identify(def, db, run);
  if (r.interrupted) {
    std::cerr << "pamsim identify: interrupted with " << db.size() << " points stored; finish "
              << "with: pamsim identify " << opt.file << " --db " << where.path << " --out "
              << where.out << " --resume\n";
    throw CommandExit(128 + stop_signal());
  }
  std::optional<IdentifyPlan> plan;
  if (opt.plan) plan = plan_candidates(def, r, threads);
  publish_outputs(def, r, where.out, plots, plan);
  print_result(r, plan);
  print_ending(def, r, where.out, plots);
}

}  // namespace

void add_identify_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<IdentifyOptions>(
      app, "identify", "Fit physical parameters to a lab's recordings (CMA-ES, then Ceres)",
      identify);
  cmd->add_option("identify", opt->file, "Identification file (TOML)")->required();
  add_database_options(cmd, &opt->database, "Identification database (default DIR/identify.db)",
                       "Continue the identification stored in the database",
                       "Output folder (default renders/<identification file name>)");
  cmd->add_flag("--force", opt->force, "Replace another identification's outputs in the folder");
  cmd->add_flag("--quiet", opt->quiet, "No progress lines");
  cmd->add_flag("--no-plot", opt->no_plot, "Write no figures (gnuplot not needed)");
  cmd->add_flag("--plan", opt->plan,
                "Then rank the file's [[candidate]] experiments by how much each would shrink "
                "the parameters' uncertainty (plan.csv, plan.md)");
  add_plot_format_option(cmd, &opt->plot_format);
}

}  // namespace pamsim
