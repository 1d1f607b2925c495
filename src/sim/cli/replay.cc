// replay.cc: `pamsim replay DB --trial N [--out DIR] [--force] [--no-plot]`: runs trial N of a
// sweep database again, on the scenario the sweep ran it with (the base scenario stored in the
// database, its fixed keys and the point's axis values, the trial's seed), and writes what a
// sweep keeps no room for: its full trajectory.csv, its summary.json, angle.png, the resolved
// scenario.toml and provenance.json (`pamsim run --from DIR` reruns it). It then checks the
// replay against the trial's stored row: every stored metric must come out the same, bit for
// bit (exit 1 naming the first that differs, e.g. after a change to the physics).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>

#include "base/atomic_file.h"
#include "base/format.h"
#include "base/input_error.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/cli/sweep_trials.h"
#include "sim/core/metrics.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/io/outputs.h"
#include "sim/io/plot.h"
#include "sim/io/provenance.h"
#include "sim/scenario/scenario_file.h"
#include "sim/io/staged_outputs.h"
#include "sim/sweep/report.h"
#include "sim/sweep/results_db.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

struct ReplayOptions {
  std::string db;
  std::int64_t trial = -1;
  std::string out;
  bool force = false;
  bool no_plot = false;
  std::string plot_format = "png";
};

const std::vector<std::string> kReplayOutputs = [] {
  std::vector<std::string> names = {"trajectory.csv", "summary.json", kResolvedScenarioFile,
                                    kProvenanceFile};
  for (const std::string& plot : plot_file_names({"angle.png", "position.png"})) {
    names.push_back(plot);
  }
  return names;
}();

// "" if the replayed summary has every stored metric's value, else the first difference.
std::string first_difference(const std::map<std::string, DbValue>& stored,
                             const std::vector<std::string>& metric_columns,
                             const TrialSummary& replayed) {
  if (stored.at("status").text != replayed.status) {
    return "status: stored " + stored.at("status").text + ", replayed " + replayed.status;
  }
  for (const std::string& name : metric_columns) {
    if (is_timing_metric(name)) continue;
    const DbValue& s = stored.at(name);
    double value = NAN;
    for (const Metric& m : replayed.metrics) {
      if (m.name == name) value = m.value;
    }
    const bool stored_defined = s.kind == DbValue::Kind::kNumber && std::isfinite(s.number);
    const bool same = stored_defined ? value == s.number : !std::isfinite(value);
    if (!same) {
      return name + ": stored " + (stored_defined ? format_shortest(s.number) : "null") +
             ", replayed " + format_shortest(value);
    }
  }
  return "";
}

void replay(const ReplayOptions& opt) {
  const auto started = std::chrono::steady_clock::now();
  const std::string started_utc = utc_timestamp();
  if (opt.trial < 0) throw InputError("--trial must be >= 0, got " + std::to_string(opt.trial));
  const ResultsDb db = ResultsDb::open_existing(opt.db);
  const SweepSummary sweep = summarize_sweep(db);
  const StoredTrial stored = stored_trial(db, sweep, opt.trial);
  const std::uint64_t seed = stored.seed;
  const std::string out =
      !opt.out.empty() ? opt.out
                       : (fs::path(opt.db).parent_path() / (fs::path(opt.db).stem().string() +
                                                            "_trial_" + std::to_string(opt.trial)))
                             .string();
  if (!opt.force) refuse_earlier_outputs(out, kReplayOutputs);
  use_plot_formats(opt.plot_format);
  const bool plots = plots_wanted(opt.no_plot);
  const RecordedScenario recorded = load_recorded_scenario(
      sweep.base_scenario, sweep.base_path, stored.overrides, out,
      "# Trial " + std::to_string(opt.trial) + " of the sweep in " + opt.db + " (point " +
          std::to_string(stored.point) + ", seed " + std::to_string(seed) +
          "), resolved by pamsim " PAMSIM_VERSION
          "\n# (provenance.json beside it says how); "
          "pamsim run --from <this folder> runs it again\n");
  const Scenario& sc = recorded.scenario;
  const TrialModel model = load_trial_model(sc);
  StagedOutputs staged(out, kReplayOutputs);
  const TrialResult result = run_trial(model, sc, seed, true);

  Provenance provenance;
  provenance.command = "replay";
  provenance.scenario_file = sweep.base_path;
  provenance.overrides = stored.overrides;
  provenance.from = opt.db;
  provenance.seeds = {seed};
  provenance.threads = 1;
  provenance.started_utc = started_utc;
  provenance.trials.push_back(timing_of(result.summary));
  provenance.inputs = fingerprint_inputs(recorded.input_paths);
  staged.write([&] {
    write_trial_outputs(staged.staging(), result, sc);
    if (plots) write_angle_plot(staged.path(trial_plot_name(result.trajectory)), result, sc);
    write_file_atomically(staged.path(kResolvedScenarioFile), recorded.resolved_toml);
    write_provenance(staged.path(kProvenanceFile), provenance, started);
  });
  staged.publish();
  std::cout << summary_to_json(result.summary, sc, false).dump(2) << "\n";
  std::cerr << "pamsim: outputs in " << out << "\n";
  const std::string difference = first_difference(stored.row, db.metric_columns(), result.summary);
  if (!difference.empty()) {
    throw std::runtime_error(opt.db + ": trial " + std::to_string(opt.trial) +
                             " replayed differently from its stored row (" + difference +
                             "); was the sweep run by another pamsim version (" +
                             db.meta("pamsim_version") + ")?");
  }
  std::cerr << "pamsim: the replay equals the stored trial (status and "
            << db.metric_columns().size() << " metric columns, timing aside)\n";
}

}  // namespace

void add_replay_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<ReplayOptions>(
      app, "replay",
      "Run one trial of a sweep database again, with its full time series, and check "
      "it against the stored row",
      replay);
  cmd->add_option("db", opt->db, "Sweep database (from pamsim sweep)")->required();
  cmd->add_option("--trial", opt->trial, "The trial's number (the trial column)")->required();
  cmd->add_option("--out", opt->out,
                  "Output folder (default: <database folder>/<database name>_trial_<N>)");
  cmd->add_flag("--force", opt->force, "Replace the outputs of an earlier replay in the folder");
  cmd->add_flag("--no-plot", opt->no_plot, "Write no plot (gnuplot not needed)");
  add_plot_format_option(cmd, &opt->plot_format);
}

}  // namespace pamsim
