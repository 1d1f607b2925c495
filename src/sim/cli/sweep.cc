// sweep.cc: `pamsim sweep SWEEP.toml [--threads N] [--db FILE] [--resume] [--out DIR]
// [--shard I/N]`: validates the sweep file and every point's scenario, then runs the trials
// (all, or shard I of N, see SweepShard) into the results database (default DIR/sweep.db, or
// DIR/sweep.shard-I-of-N.db for a shard; DIR default renders/<sweep name>). SIGINT or SIGTERM
// stops it cleanly (running trials finish and are stored; exit 130 or 143); --resume finishes
// the rest. `pamsim merge` combines the shards' databases.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <signal.h>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <stdexcept>

#include "base/input_error.h"
#include "sim/cli/command_database.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/cli/progress.h"
#include "sim/cli/stop_signal.h"
#include "sim/io/build_info.h"
#include "sim/io/outputs.h"
#include "sim/io/provenance.h"
#include "sim/sweep/results_db.h"
#include "sim/io/sqlite_file.h"
#include "sim/core/runner.h"
#include "sim/sweep/sweep.h"
#include "sim/sweep/sweep_runner.h"
#ifdef PAMSIM_HAVE_MPI
#include "base/format.h"
#include "sim/sweep/mpi_sweep.h"
#endif

namespace pamsim {
namespace {

struct SweepOptions {
  std::string sweep_file;
  DatabaseOptions database;
  std::string shard;
  bool quiet = false;
};

// Where the trials run when not on this machine's threads: rank 0 of an MPI job hands them
// to the other ranks, which start once it has opened the database and said so.
struct RemoteTrials {
  std::string where;  // " on 2 MPI worker ranks"
  std::function<void()> database_opened;
  std::function<SweepRunResult(const SweepDefinition&, ResultsDb&, const SweepRunOptions&)> run;
};

// What ran, and what to do next: finish an interrupted sweep, merge shards, or report.
void report_sweep_run(const SweepOptions& opt, const SweepRunResult& r, const SweepShard& shard,
                      const CommandDatabase& where, std::int64_t trials) {
  const std::string& db_path = where.path;
  const std::int64_t stored = r.already_done + r.ran;
  char rate[32];
  std::snprintf(rate, sizeof(rate), "%.1f", r.wall_time_s > 0 ? r.ran / r.wall_time_s : 0.0);
  std::cerr << "pamsim sweep: " << r.ran << " trials run in " << format_duration(r.wall_time_s)
            << " (" << rate << " trials/s)";
  if (r.already_done > 0) std::cerr << ", " << r.already_done << " stored before";
  if (r.diverged > 0) std::cerr << "; " << r.diverged << " diverged or failed (see their status)";
  std::cerr << "\n";
  if (r.interrupted) {
    const std::string finish = std::to_string(stored) + " of " + std::to_string(trials) +
                               " trials stored; finish with: pamsim sweep " + opt.sweep_file +
                               " --db " + db_path +
                               (shard.whole() ? "" : " --shard " + shard.text()) + " --resume";
    if (!r.incomplete_reason.empty()) throw std::runtime_error(r.incomplete_reason + "; " + finish);
    std::cerr << "pamsim sweep: interrupted with " << finish << "\n";
    throw CommandExit(128 + stop_signal());  // the shell's code for that signal
  }
  std::cout << db_path << "\n";
  if (!shard.whole()) {
    std::cerr << "pamsim sweep: next, when every shard is done: pamsim merge " << where.out
              << "/sweep.db " << where.out << "/sweep.shard-*-of-" << shard.count << ".db\n";
    return;
  }
  std::cerr << "pamsim sweep: next: pamsim export " << db_path << " -o FILE; pamsim report "
            << db_path << "\n";
}

// The sweep on this machine's threads, or with `remote` (when not null).
void run_sweep_command(const SweepOptions& opt, const RemoteTrials* remote) {
  const std::string started_utc = utc_timestamp();
  const int threads = resolve_thread_count(opt.database.threads);
  const SweepShard shard =
      opt.shard.empty() ? SweepShard{} : parse_sweep_shard(opt.shard, "--shard");
  const SweepDefinition def = load_sweep(opt.sweep_file);  // everything validated first
  const std::string db_name = shard.whole() ? "sweep.db"
                                            : "sweep.shard-" + std::to_string(shard.index) +
                                                  "-of-" + std::to_string(shard.count) + ".db";
  const CommandDatabase where = command_database(opt.sweep_file, opt.database, db_name);
  const std::string& db_path = where.path;
  const std::int64_t trials = shard.trials_of(def.trials());
  ResultsDb db = open_in_database_folder(where, db_name, [&] {
    return opt.database.resume && where.exists ? ResultsDb::open_to_resume(db_path, def, shard)
                                               : ResultsDb::create(db_path, def, shard);
  });
  if (remote) remote->database_opened();
  warn_if_other_version("sweep", db_path, db.meta("pamsim_version"), "trials");
  std::cerr << "pamsim sweep: " << def.points() << " points x " << def.seeds
            << " seeds = " << def.trials() << " trials (" << sweep_design_name(def.design) << ")";
  if (!shard.whole()) std::cerr << ", shard " << shard.text() << ": " << trials << " trials";
  if (remote)
    std::cerr << remote->where;
  else
    std::cerr << " on " << threads << (threads == 1 ? " thread" : " threads");
  std::cerr << " into " << db_path << "\n";

  StopOnSignal stop_on_signal;
  ProgressReporter progress("pamsim sweep", trials, db.trial_count(), std::cerr,
                            progress_style(opt.quiet));
  SweepRunOptions run_options;
  run_options.threads = threads;
  run_options.shard = shard;
  run_options.stop = &stop_requested();
  run_options.on_progress = [&](std::int64_t stored) { progress.update(stored); };
  const SweepRunResult r =
      remote ? remote->run(def, db, run_options) : run_sweep(def, db, run_options);
  const std::int64_t stored = r.already_done + r.ran;
  progress.finish(stored);
  // what ran into the database, beside its trials (interrupted runs too)
  db.record_invocation({{"command_line", command_line()},
                        {"threads", remote ? nlohmann::json(nullptr) : nlohmann::json(threads)},
                        {"shard", shard.text()},
                        {"started_utc", started_utc},
                        {"wall_time_s", r.wall_time_s},
                        {"trials_run", r.ran},
                        {"interrupted", r.interrupted},
                        {"build", build_info_json()}});

  report_sweep_run(opt, r, shard, where, trials);
}

#ifdef PAMSIM_HAVE_MPI
// A rank other than 0 of an MPI job: waits for rank 0 to open the database, then runs the
// trials it hands out, on --threads threads (default: this node's cores shared among its
// ranks). Says nothing: rank 0 reports for the job.
void run_mpi_worker(const SweepOptions& opt, const MpiSession& mpi) {
  if (!mpi.broadcast_go(false)) return;  // rank 0 refused the sweep and said why
  SweepDefinition def;
  std::string load_error;
  try {
    def = load_sweep(opt.sweep_file);
  } catch (const std::exception& e) {
    load_error = e.what();
  }
  const int threads = opt.database.threads > 0
                          ? resolve_thread_count(opt.database.threads)
                          : std::max(1, resolve_thread_count(0) / mpi.ranks_on_this_node());
  StopOnSignal stop_on_signal;
  work_mpi_sweep(mpi, def, threads, &stop_requested(), load_error);
}
#endif

void sweep(const SweepOptions& opt) {
#ifdef PAMSIM_HAVE_MPI
  if (MpiSession::launched()) {
    MpiSession mpi;
    if (mpi.rank() > 0) return run_mpi_worker(opt, mpi);
    if (mpi.size() > 1) {
      RemoteTrials ranks;
      ranks.where = " on " + std::to_string(mpi.size() - 1) + " MPI worker ranks";
      ranks.database_opened = [&] { mpi.broadcast_go(true); };
      ranks.run = [&](const SweepDefinition& def, ResultsDb& db, const SweepRunOptions& o) {
        return coordinate_mpi_sweep(mpi, def, db, o);
      };
      try {
        return run_sweep_command(opt, &ranks);
      } catch (const CommandExit&) {
        throw;  // interrupted: the workers have sent what they ran and ended
      } catch (const std::exception& e) {
        // refused before the database was open: the workers are told and end quietly
        if (!mpi.decided()) {
          mpi.broadcast_go(false);
          throw;
        }
        if (mpi.workers_done()) throw;  // nobody waits for rank 0 any more
        // later (the database cannot be written): the workers would wait for ever
        std::cerr << "pamsim: error: " << printable_message(e.what()) << "\n";
        mpi.abort(1);
      }
    }
  }
#else
  // every rank would run the whole sweep into the same database
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const char* size = std::getenv(var);
    if (size && std::atoi(size) > 1) {
      throw InputError(
          "pamsim sweep: this pamsim was built without MPI, so under mpirun every "
          "rank would run the whole sweep; build with -DPAMSIM_MPI=ON, or use "
          "--shard I/N");
    }
  }
#endif
  run_sweep_command(opt, nullptr);
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<SweepOptions>(
      app, "sweep", "Run a parameter sweep into an SQLite database", sweep);
  cmd->add_option("sweep", opt->sweep_file, "Sweep file (TOML)")->required();
  add_database_options(cmd, &opt->database, "Results database (default DIR/sweep.db)",
                       "Finish the sweep stored in the database",
                       "Output folder (default renders/<sweep name>)");
  cmd->add_flag("--quiet", opt->quiet, "No progress bar or progress lines");
  cmd->add_option("--shard", opt->shard,
                  "Run only shard I of N (0 <= I < N; trial t is in shard t mod N) into its own "
                  "database (default DIR/sweep.shard-I-of-N.db); combine with pamsim merge");
}

}  // namespace pamsim
