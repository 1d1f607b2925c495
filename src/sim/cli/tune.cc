// tune.cc: `pamsim tune TUNE.toml [--db FILE] [--out DIR] [--threads N] [--resume]`: tunes a
// scenario's settings with pagmo2's CMA-ES or NSGA-II (src/sim/optimize/tune.h), every
// evaluation stored in SQLite as it finishes; then checks the best setting and the file's
// references on held-out seeds and writes best.toml, evaluations.csv, convergence.png (and
// the Pareto front). Everything is validated before the database is created. A killed run
// keeps every finished evaluation; --resume replays the optimiser with them and goes on.
#include "sim/optimize/tune_outputs.h"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "sim/cli/command_database.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/cli/progress.h"
#include "sim/cli/stop_signal.h"
#include "sim/core/runner.h"
#include "sim/io/outputs.h"
#include "sim/io/plot.h"
#include "sim/io/staged_outputs.h"

namespace pamsim {
namespace {

struct TuneOptions {
  std::string file;
  DatabaseOptions database;
  bool force = false;
  bool no_plot = false;
  bool quiet = false;
  std::string plot_format = "png";
};

// The checks of settings as a table on stdout, under `what`.
void print_checks(const TuneDefinition& def, const std::vector<HeldOutCheck>& checks,
                  const std::string& what) {
  std::ostringstream table;
  table << what << ":\n";
  for (const HeldOutCheck& c : checks) {
    table << "  " << c.name << ":";
    for (std::size_t i = 0; i < c.values.size(); ++i) {
      table << (i ? ", " : " ") << def.parameters[i].key << " = " << format_value(c.values[i]);
    }
    for (std::size_t i = 0; i < c.objectives.size(); ++i) {
      table << "; " << def.objectives[i].metric << " " << format_value(c.objectives[i]);
    }
    for (std::size_t i = 0; i < c.constraints.size(); ++i) {
      table << "; " << def.constraints[i].metric << " " << format_value(c.constraints[i]);
    }
    table << (c.violation == 0.0 ? "" : " (breaks a constraint)") << "\n";
  }
  std::cout << table.str();
}

// The search itself, with progress (under the caller's StopOnSignal); a stop leaves the
// database to --resume.
TuneRunResult run_search_command(const TuneOptions& opt, const TuneDefinition& def, TuneDb& db,
                                 const CommandDatabase& where, int threads) {
  const std::int64_t total = def.search().evaluations();
  std::cerr << "pamsim tune: " << (def.algorithm == TuneAlgorithm::kCmaes ? "CMA-ES" : "NSGA-II")
            << ", " << def.generations << " generations of " << def.population << " (" << total
            << " evaluations) x " << def.seeds * def.noise_scales.size() << " trials each, on "
            << threads << (threads == 1 ? " thread" : " threads") << " into " << where.path << "\n";
  ProgressReporter progress("pamsim tune", total, 0, std::cerr, progress_style(opt.quiet),
                            "evaluations");
  warn_if_other_version("tune", where.path, db.meta("pamsim_version"), "evaluations");
  TuneRunOptions run;
  run.threads = threads;
  run.stop = &stop_requested();
  std::int64_t calls = 0;
  run.on_evaluation = [&](std::int64_t done, std::int64_t, bool) { progress.update(calls = done); };
  TuneRunResult r = run_tune(def, db, run);
  progress.finish(calls);
  if (r.cached > 0) {
    std::cerr << "pamsim tune: " << r.cached
              << " proposals answered from the database (stored before, or proposed again)\n";
  }
  if (r.interrupted) {
    std::cerr << "pamsim tune: interrupted with " << r.history.size()
              << " evaluations stored; finish with: pamsim tune " << opt.file << " --db "
              << where.path << " --out " << where.out << " --resume\n";
    throw CommandExit(128 + stop_signal());
  }
  return r;
}

// The best and the references, on the tuning seeds and on held-out ones: tuning_seeds.csv,
// held_out.csv and their tables on stdout.
void check_settings(const TuneDefinition& def, const std::vector<TuneEvaluation>& history,
                    const StagedOutputs& staged, int threads) {
  const TuneEvaluation* best = best_evaluation(history);
  std::vector<TuneReference> settings = {
      {"tuned (evaluation " + std::to_string(best->index) + ")", best->values}};
  settings.insert(settings.end(), def.references.begin(), def.references.end());
  const std::vector<HeldOutCheck> on_tuning = check_held_out(def, settings, threads, true);
  staged.write([&] {
    write_file_atomically(staged.path("tuning_seeds.csv"), held_out_csv(def, on_tuning));
  });
  print_checks(def, on_tuning,
               "on the tuning seeds (" + std::to_string(def.seeds) + " seeds x " +
                   std::to_string(def.noise_scales.size()) + " noise levels)");
  if (def.held_out_seeds > 0) {
    const std::vector<HeldOutCheck> checks = check_held_out(def, settings, threads);
    staged.write(
        [&] { write_file_atomically(staged.path("held_out.csv"), held_out_csv(def, checks)); });
    print_checks(def, checks,
                 "held-out check (" + std::to_string(def.held_out_seeds) + " seeds x " +
                     std::to_string(def.noise_scales.size()) +
                     " noise levels, not used in tuning)");
  }
}

void tune(const TuneOptions& opt) {
  const int threads = resolve_thread_count(opt.database.threads);
  const TuneDefinition def = load_tune_definition(opt.file);  // everything validated first
  const CommandDatabase where = command_database(opt.file, opt.database, "tune.db");
  if (opt.database.resume && !where.exists) {
    throw InputError(where.path + ": --resume, but there is no database");
  }
  // a new tuning does not replace another's outputs silently (a resumed one replaces its own)
  if (!opt.database.resume && !where.exists && !opt.force)
    refuse_earlier_outputs(where.out, kTuneOutputs);
  use_plot_formats(opt.plot_format);
  const bool plots = plots_wanted(opt.no_plot);
  TuneDb db = open_in_database_folder(where, "tune.db", [&] {
    return opt.database.resume ? TuneDb::open_to_resume(where.path, def)
                               : TuneDb::create(where.path, def);
  });
  StopOnSignal stop_on_signal;  // until the end: a signal stops the search, not the checks
  const TuneRunResult r = run_search_command(opt, def, db, where, threads);
  // the outputs are published together once all are written (tune.db stays where it is)
  StagedOutputs staged(where.out, kTuneOutputs);
  staged.write([&] { write_tune_outputs(def, r.history, staged, plots); });
  check_settings(def, r.history, staged, threads);
  staged.publish();
  std::cout << "outputs: " << where.out << "/{best.toml,evaluations.csv,convergence.png"
            << (def.objectives.size() > 1 ? ",pareto.csv,pareto.png" : "") << ",tuning_seeds.csv"
            << (def.held_out_seeds > 0 ? ",held_out.csv" : "") << "}\n";
}

}  // namespace

void add_tune_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<TuneOptions>(
      app, "tune", "Tune a scenario's settings with CMA-ES or NSGA-II (pagmo2) into SQLite", tune);
  cmd->add_option("tune", opt->file, "Tuning file (TOML)")->required();
  add_database_options(cmd, &opt->database, "Tuning database (default DIR/tune.db)",
                       "Continue the tuning stored in the database",
                       "Output folder (default renders/<tuning file name>)");
  cmd->add_flag("--force", opt->force, "Replace another tuning's outputs in the folder");
  cmd->add_flag("--no-plot", opt->no_plot, "Write no figures (gnuplot not needed)");
  cmd->add_flag("--quiet", opt->quiet, "No progress bar or progress lines");
  add_plot_format_option(cmd, &opt->plot_format);
}

}  // namespace pamsim
