// validate.cc: `pamsim validate length-estimation [FILE] [--out DIR] [--pams A,B]` and
// `pamsim validate reaching [FILE] [--out DIR]`, both with `--set key=value`, `--seed N`
// and `--threads N`: the papers' validation experiments (Yoshida and Hosoda, Table III and
// Table V) as protocols over data files (scenarios/validate_*.toml; src/sim/validate/).
// Inputs are all read and checked before any trial runs; the tables are written last, each
// atomically. With `--budget`, each the protocol's error budget instead
// (validate/protocol_budgets.h).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/cli/progress.h"
#include "sim/core/runner.h"
#include "sim/io/html_page.h"
#include "sim/io/outputs.h"
#include "sim/io/plot.h"
#include "sim/io/provenance.h"
#include "sim/io/staged_outputs.h"
#include "sim/validate/length_estimation.h"
#include "sim/validate/protocol_bands.h"
#include "sim/validate/protocol_budgets.h"
#include "sim/validate/reaching.h"

namespace pamsim {
namespace {

struct ValidateOptions {
  std::string file;
  std::string out;
  std::vector<std::string> overrides;
  std::vector<std::string> pams;
  std::optional<std::uint64_t> seed;
  int threads = 0;
  bool force = false;
  bool budget = false;
  std::optional<int> bands;  // --bands N
  bool sensitivity = false;
  bool assumptions = false;  // --assumptions
  bool no_plot = false;
  bool quiet = false;
  std::string plot_format = "png";
};

const std::vector<std::string> kLengthOutputs = [] {
  std::vector<std::string> names = {"table3.csv", "table3.md", "fits", kProvenanceFile,
                                    kReportPageFile};
  for (const std::string& plot : plot_file_names({"pam_*.png"})) names.push_back(plot);
  return names;
}();
const std::vector<std::string> kReachingOutputs = [] {
  std::vector<std::string> names = {"table5.csv", "table5.md", kProvenanceFile, kReportPageFile};
  for (const std::string& plot : plot_file_names({"fig7.png"})) names.push_back(plot);
  return names;
}();

const std::vector<std::string> kBudgetOutputs = [] {
  std::vector<std::string> names = {"budget.csv", "budget.md", kProvenanceFile, kReportPageFile};
  for (const std::string& plot : plot_file_names({"budget.png"})) names.push_back(plot);
  return names;
}();

const std::vector<std::string> kBandsOutputs = [] {
  std::vector<std::string> names = {"bands.csv", "bands.md", "draws.csv", kProvenanceFile,
                                    kReportPageFile};
  for (const std::string& plot : plot_file_names({"bands.png"})) names.push_back(plot);
  return names;
}();
const std::vector<std::string> kSensitivityOutputs = {"sensitivity.csv", "sensitivity.md",
                                                      kProvenanceFile, kReportPageFile};

// provenance.json of a validation: its protocol file, overrides, seed and threads.
void write_validation_provenance(const ValidateOptions& o, const ValidationOptions& v,
                                 const std::string& command, const std::string& path,
                                 std::chrono::steady_clock::time_point started,
                                 const std::string& started_utc) {
  Provenance p;
  p.command = command;
  p.scenario_file = o.file;
  p.overrides = o.overrides;
  if (o.seed) p.seeds = {*o.seed};
  p.threads = v.threads;
  p.started_utc = started_utc;
  write_provenance(path, p, started);
}

ValidationOptions common_options(const ValidateOptions& o, const std::string& default_out) {
  ValidationOptions v;
  v.out_dir = o.out.empty() ? default_out : o.out;
  v.overrides = o.overrides;
  v.seed = o.seed;
  v.threads = resolve_thread_count(o.threads);
  return v;
}

// --assumptions changes only which brackets a band or sensitivity run draws
void refuse_stray_assumptions(const ValidateOptions& o) {
  if (o.assumptions && !o.bands && !o.sensitivity) {
    throw InputError("--assumptions needs --bands or --sensitivity");
  }
}

// A folder this command made for its outputs: removed again if the command is refused
// before it writes there (the folder is still empty), so that bad input leaves nothing behind.
class MadeFolder {
 public:
  MadeFolder(std::string dir, bool made) : dir_(std::move(dir)), made_(made) {}
  MadeFolder(const MadeFolder&) = delete;
  MadeFolder& operator=(const MadeFolder&) = delete;
  ~MadeFolder() {
    std::error_code ec;  // (a folder that holds anything is not removed)
    if (made_ && std::uncaught_exceptions() > 0) std::filesystem::remove(dir_, ec);
  }

 private:
  std::string dir_;
  bool made_;
};

// An output folder that exists and takes a file, checked before any trial runs (a read-only
// folder would otherwise fail only at the end); made here if missing.
[[nodiscard]] std::unique_ptr<MadeFolder> require_writable(const std::string& dir) {
  const bool existed = std::filesystem::exists(dir);
  make_directories(dir);
  auto made = std::make_unique<MadeFolder>(dir, !existed);
  const std::filesystem::path probe =
      std::filesystem::path(dir) / (".pamsim_write_test." + std::to_string(::getpid()));
  std::ofstream out(probe);
  const bool ok = out && (out << "x") && (out.close(), !out.fail());
  std::error_code ec;
  std::filesystem::remove(probe, ec);
  if (!ok) throw InputError("--out " + dir + ": cannot write there");
  return made;
}

// "length_estimation" (a default folder's part) -> "length-estimation", as the user types it
std::string subcommand(std::string name) {
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

void attach_progress(ValidationOptions* v, const std::string& label, int total, bool quiet,
                     std::shared_ptr<ProgressReporter>* holder) {
  *holder = std::make_shared<ProgressReporter>(label, total, 0, std::cerr, progress_style(quiet));
  ProgressReporter* p = holder->get();
  v->progress = [p](int done, int) { p->update(done); };
}

// --budget: runs `run` (a protocol's budget of `sources`, protocol_budgets.h, `trials` per
// run of the protocol) and writes budget.csv, budget.md and budget.png into --out (default
// renders/validate_<name>_budget)
void run_budget_command(const ValidateOptions& o, const std::string& name,
                        const std::vector<BudgetSource>& sources, int trials,
                        const std::function<ErrorBudget(const ValidationOptions&)>& run) {
  const auto started = std::chrono::steady_clock::now();
  const std::string started_utc = utc_timestamp();
  ValidationOptions v = common_options(o, "renders/validate_" + name + "_budget");
  if (!o.force) refuse_earlier_outputs(v.out_dir, kBudgetOutputs);
  use_plot_formats(o.plot_format);
  const bool plots = plots_wanted(o.no_plot);
  const auto folder = require_writable(v.out_dir);
  const std::string command = "validate " + subcommand(name) + " --budget";
  const int total = trials * static_cast<int>(budget_configs(sources).size());
  std::shared_ptr<ProgressReporter> progress;
  attach_progress(&v, "pamsim " + command, total, o.quiet, &progress);
  v.started = [&](int n) {
    std::cerr << "pamsim validate: error budget of " << sources.size() << " sources, " << n
              << " trials on " << v.threads << (v.threads == 1 ? " thread" : " threads") << "\n";
  };
  const ErrorBudget budget = run(v);
  progress->finish(total);
  StagedOutputs staged(v.out_dir, kBudgetOutputs);
  staged.write([&] {
    write_error_budget(budget, staged.staging(), plots);
    write_validation_provenance(o, v, command, staged.path(kProvenanceFile), started, started_utc);
  });
  staged.publish();
  std::cout << budget_markdown(budget);
  std::cerr << "pamsim validate: outputs in " << v.out_dir << " (budget.csv, budget.md"
            << (plots ? ", budget.png)\n" : ")\n");
}

// --bands N or --sensitivity: runs the protocol's `bands` (protocol_bands.h) or its
// `sensitivity` and writes their files into --out (default renders/validate_<name>_bands or
// _sensitivity)
void run_bands_command(const ValidateOptions& o, const std::string& name,
                       const std::function<Bands(const ValidationOptions&)>& bands,
                       const std::function<Sensitivity(const ValidationOptions&)>& sensitivity) {
  const auto started = std::chrono::steady_clock::now();
  const std::string started_utc = utc_timestamp();
  const bool banded = o.bands.has_value();
  if (banded) check_band_rigs(*o.bands);  // before any folder is made
  const std::string what = banded ? "bands" : "sensitivity";
  ValidationOptions v = common_options(o, "renders/validate_" + name + "_" + what);
  v.assumptions = o.assumptions;
  const std::vector<std::string>& outputs = banded ? kBandsOutputs : kSensitivityOutputs;
  if (!o.force) refuse_earlier_outputs(v.out_dir, outputs);
  use_plot_formats(o.plot_format);
  const bool plots = plots_wanted(o.no_plot);
  const auto folder = require_writable(v.out_dir);
  const std::string command =
      "validate " + subcommand(name) +
      (banded ? " --bands " + std::to_string(*o.bands) : std::string(" --sensitivity")) +
      (o.assumptions ? " --assumptions" : "");
  std::shared_ptr<ProgressReporter> progress;
  int total = 0;
  v.started = [&](int n) {
    total = n;
    std::cerr << "pamsim " << command << ": " << n << " trials on " << v.threads
              << (v.threads == 1 ? " thread" : " threads") << "\n";
    attach_progress(&v, "pamsim " + command, n, o.quiet, &progress);
  };
  v.progress = [&](int done, int) {
    if (progress) progress->update(done);
  };
  std::optional<Bands> b;
  std::optional<Sensitivity> s;
  if (banded)
    b = bands(v);
  else
    s = sensitivity(v);
  if (progress) progress->finish(total);
  StagedOutputs staged(v.out_dir, outputs);
  staged.write([&] {
    if (b) write_bands(*b, staged.staging(), plots);
    if (s) write_sensitivity(*s, staged.staging());
    write_validation_provenance(o, v, command, staged.path(kProvenanceFile), started, started_utc);
  });
  staged.publish();
  std::cout << (b ? bands_markdown(*b) : sensitivity_markdown(*s));
  std::cerr << "pamsim validate: outputs in " << v.out_dir << "\n";
}

void run_length_estimation(const ValidateOptions& o) {
  const auto started = std::chrono::steady_clock::now();
  const std::string started_utc = utc_timestamp();
  refuse_stray_assumptions(o);
  const LengthValidationSpec spec = load_length_validation(o.file, o.pams);
  if (o.bands || o.sensitivity) {
    return run_bands_command(
        o, "length_estimation",
        [&](const ValidationOptions& v) { return run_length_bands(spec, v, *o.bands); },
        [&](const ValidationOptions& v) { return run_length_sensitivity(spec, v); });
  }
  if (o.budget) {
    return run_budget_command(
        o, "length_estimation", spec.budget, static_cast<int>(spec.pams.size()),
        [&](const ValidationOptions& v) { return run_length_budget(spec, v); });
  }
  ValidationOptions v = common_options(o, "renders/validate_length_estimation");
  if (!o.force) refuse_earlier_outputs(v.out_dir, kLengthOutputs);
  use_plot_formats(o.plot_format);
  const bool plots = plots_wanted(o.no_plot);
  const auto folder = require_writable(v.out_dir);  // unwritable: fails before any work
  const int total = static_cast<int>(spec.pams.size() * spec.laws.size() * spec.weights_kg.size());
  std::shared_ptr<ProgressReporter> progress;
  attach_progress(&v, "pamsim validate length-estimation", total, o.quiet, &progress);
  v.started = [&](int trials) {
    std::cerr << "pamsim validate: " << spec.pams.size() << " PAMs x " << spec.laws.size()
              << " laws x " << spec.weights_kg.size() << " weights = " << trials
              << " dynamic trials on " << v.threads << (v.threads == 1 ? " thread" : " threads")
              << "\n";
  };
  LengthValidationResult result = run_length_validation(spec, v);
  progress->finish(total);
  // published together: a failure half way, or a rerun with fewer figures, leaves no mix
  StagedOutputs staged(v.out_dir, kLengthOutputs);
  staged.write([&] {
    write_length_validation(result, spec, staged.staging(), plots);
    write_validation_provenance(o, v, "validate length-estimation", staged.path(kProvenanceFile),
                                started, started_utc);
  });
  staged.publish();
  std::cout << table3_markdown(result, spec);
  std::cerr << "pamsim validate: outputs in " << v.out_dir
            << " (table3.csv, table3.md, pam_*.png, fits/)\n";
}

void run_reaching(const ValidateOptions& o) {
  const auto started = std::chrono::steady_clock::now();
  const std::string started_utc = utc_timestamp();
  refuse_stray_assumptions(o);
  const ReachingValidationSpec spec = load_reaching_validation(o.file);
  if (o.bands || o.sensitivity) {
    return run_bands_command(
        o, "reaching",
        [&](const ValidationOptions& v) { return run_reaching_bands(spec, v, *o.bands); },
        [&](const ValidationOptions& v) { return run_reaching_sensitivity(spec, v); });
  }
  if (o.budget) {
    return run_budget_command(
        o, "reaching", spec.budget, spec.trials,
        [&](const ValidationOptions& v) { return run_reaching_budget(spec, v); });
  }
  ValidationOptions v = common_options(o, "renders/validate_reaching");
  if (!o.force) refuse_earlier_outputs(v.out_dir, kReachingOutputs);
  use_plot_formats(o.plot_format);
  const bool plots = plots_wanted(o.no_plot);
  const auto folder = require_writable(v.out_dir);
  std::shared_ptr<ProgressReporter> progress;
  attach_progress(&v, "pamsim validate reaching", spec.trials, o.quiet, &progress);
  const ReachingValidationResult result = run_reaching_validation(spec, v);
  progress->finish(spec.trials);
  StagedOutputs staged(v.out_dir, kReachingOutputs);
  staged.write([&] {
    write_reaching_validation(result, spec, staged.staging(), plots);
    write_validation_provenance(o, v, "validate reaching", staged.path(kProvenanceFile), started,
                                started_utc);
  });
  staged.publish();
  std::cout << table5_markdown(result, spec);
  std::cerr << "pamsim validate: outputs in " << v.out_dir
            << " (table5.csv, table5.md, fig7.png)\n";
}

void add_common(CLI::App* cmd, ValidateOptions* o, const std::string& default_file) {
  o->file = default_file;
  cmd->add_option("file", o->file, "Validation protocol (TOML)")->capture_default_str();
  cmd->add_option("--out", o->out, "Output folder (default renders/validate_<name>)");
  cmd->add_option("--set", o->overrides,
                  "Override a scenario key of every trial: --set sensors.noise_scale=2");
  cmd->add_option("--seed", o->seed, "Seed of the trials (and of the tensile tests' noise)")
      ->check(non_negative_seed);
  cmd->add_option("--threads", o->threads, "Worker threads (0: all cores)")->capture_default_str();
  cmd->add_flag("--force", o->force, "Replace the outputs of an earlier validation in the folder");
  cmd->add_flag("--budget", o->budget,
                "The error budget instead of the table: the protocol with each hardware error "
                "source ([[budget_source]]) on and off (budget.csv, budget.md, budget.png)");
  CLI::Option* bands = cmd->add_option(
      "--bands", o->bands,
      "Run the protocol on N rigs drawn from the file's [[bracket]] tables, every hardware "
      "source on: each cell as median [5 %, 95 %] with the paper's value beside (bands.csv, "
      "bands.md, draws.csv, bands.png)");
  CLI::Option* sensitivity =
      cmd->add_flag("--sensitivity", o->sensitivity,
                    "Each [[bracket]] alone at its two ends: which unknown moves which cell "
                    "(sensitivity.csv, sensitivity.md)");
  cmd->add_flag("--assumptions", o->assumptions,
                "With --bands or --sensitivity: draw the [[bracket]] tables marked assumption "
                "too (without it they hold the scenario's values, and the headline count is "
                "the sourced brackets' alone)");
  bands->excludes(sensitivity);
  cmd->get_option("--budget")->excludes(bands)->excludes(sensitivity);
  cmd->add_flag("--no-plot", o->no_plot, "Write no figures (gnuplot not needed)");
  cmd->add_flag("--quiet", o->quiet, "No progress bar or progress lines");
  add_plot_format_option(cmd, &o->plot_format);
}

}  // namespace

void add_validate_command(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand(
      "validate", "the papers' validation experiments: Table III and Table V in simulation");
  cmd->require_subcommand(1);

  const auto [le, length] = add_command<ValidateOptions>(
      *cmd, "length-estimation",
      "PAMs A-D: tensile test, fits of Eq. (3)-(5), dynamic test on the pulley (Table III)",
      run_length_estimation);
  add_common(le, length.get(), "scenarios/validate_length_estimation.toml");
  le->add_option("--pams", length->pams, "Only these PAMs (comma-separated names)")->delimiter(',');

  const auto [re, reaching] = add_command<ValidateOptions>(
      *cmd, "reaching",
      "the arm's reaching task: model estimate and fiber sensor vs encoder (Table V)",
      run_reaching);
  add_common(re, reaching.get(), "scenarios/validate_reaching.toml");
}

}  // namespace pamsim
