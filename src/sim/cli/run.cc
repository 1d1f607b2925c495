// run.cc: `pamsim run SCENARIO.toml [--set key=value ...] [--out DIR] [--trials N]
// [--threads T] [--video FILE.mp4] [--force] [--no-plot]`, or `pamsim run --from DIR`: one
// trial (outputs in DIR, and with --video its video, rendered as in `pamsim render` with the
// default settings) or N trials (DIR/trial_<k>/ each, plus the aggregate DIR/summary.json and
// the angle band plot; no video). Every output folder also holds scenario.toml (the resolved
// scenario) and provenance.json (provenance.h); `--from DIR` runs DIR's scenario.toml again
// with DIR's trial count, and writes byte for byte the same trajectory.csv and summary.json.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "base/toml_file.h"
#include "base/units.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/cli/progress.h"
#include "sim/core/runner.h"
#include "sim/io/build_info.h"
#include "sim/io/outputs.h"
#include "sim/io/plot.h"
#include "sim/io/provenance.h"
#include "sim/view/live_session.h"  // unreproduced_live_changes
#include "sim/io/readings_csv.h"
#include "sim/scenario/scenario_file.h"
#include "sim/io/staged_outputs.h"
#include "sim/render/scene_renderer.h"
#include "sim/render/trial_video.h"
#include "sim/validate/line_breaks.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;

struct RunOptions {
  std::string scenario;
  std::string from;  // an earlier run's output folder
  std::vector<std::string> overrides;
  std::string out;
  int trials = 1;
  bool trials_given = false;
  int threads = 0;
  std::string video;  // MP4 of the single trial
  bool force = false;
  bool no_plot = false;
  bool quiet = false;
  bool readings = false;  // readings.csv: the controller's inputs, lossless
  std::string plot_format = "png";
};

// What a run writes in its folder (StagedOutputs replaces exactly these).
const std::vector<std::string> kRunOutputs = [] {
  std::vector<std::string> names = {
      "trajectory.csv", "summary.json",        "trial_[0-9][0-9][0-9][0-9]",
      "readings.csv",   kResolvedScenarioFile, kProvenanceFile};
  for (const std::string& plot : plot_file_names({"angle.png", "position.png", "angle_band.png"})) {
    names.push_back(plot);
  }
  return names;
}();

// One line per diverged trial; returns how many diverged.
int report_diverged(const Scenario& sc, const std::vector<TrialResult>& results) {
  int n = 0;
  for (const auto& r : results) {
    if (r.summary.status == "ok") continue;
    std::cerr << "pamsim: " << sc.path << ": trial with seed " << r.summary.seed << " "
              << r.summary.status << ": " << r.summary.message << "\n";
    ++n;
  }
  return n;
}

// A start the calibration did not hold: the arm settled elsewhere before the drop, because a
// muscle or its plant changed since its lines were calibrated. One line, not an error.
void warn_if_the_start_moved(const Scenario& sc, const std::vector<TrialResult>& results) {
  constexpr double kToleranceDeg = 0.5;
  if (sc.calibration_file.empty() || !sc.has_start_position || results.empty()) return;
  const double at = results.front().summary.metric("start_angle_deg");
  const double calibrated = units::rad_to_deg(sc.start_position);
  if (!std::isfinite(at) || std::fabs(at - calibrated) <= kToleranceDeg) return;
  char buf[96];
  std::snprintf(buf, sizeof(buf), "the arm starts at %.1f deg, not the %.1f deg ", at, calibrated);
  std::cerr << "pamsim: warning: " << buf << "its lines were calibrated for (model.calibration): "
            << "a muscle or its plant changed since; muscles.<m>.line = \"equilibrium\" solves "
               "a muscle's line to hold the calibrated start, or pamsim calibrate writes new "
               "lines\n";
}

// A line that breaks (muscles.<m>.line_strength_MPa): the trial ran on as if it held, which
// no rig could. One line per muscle, not an error (validation refuses such a rig,
// line_breaks.h); its pull is the tension metrics' peak of every physics step where the
// scenario has them, else the log's.
void warn_if_a_line_breaks(const Scenario& sc, const std::vector<TrialResult>& results) {
  for (const MuscleSpec& m : sc.muscles) {
    double peak = 0.0;
    for (const TrialResult& r : results) {
      const double stepped = r.summary.metric("peak_tension_" + m.label + "_N");
      peak = std::max(peak,
                      std::isfinite(stepped) ? stepped : logged_peak_tension(m, {&r.trajectory}));
    }
    const std::string problem = line_break_problem(m, peak);
    if (problem.empty()) continue;
    std::cerr << "pamsim: warning: " << sc.path << ": " << m.key
              << ".line_strength_MPa: " << problem << " (the trial ran on as if it held)\n";
  }
}

// --from DIR: the earlier run's scenario.toml with its overrides, then this run's; warns
// when an input or the build changed since. Returns the file to read.
std::string take_earlier_run(RunOptions& opt, Provenance* provenance) {
  if (!opt.scenario.empty()) {
    throw InputError("--from " + opt.from + " runs that folder's scenario.toml; drop " +
                     opt.scenario + " (or drop --from)");
  }
  const Provenance earlier = read_provenance(opt.from);
  provenance->scenario_file = earlier.scenario_file;
  provenance->from = opt.from;
  // relative to the first run's scenario file: its overrides, then this run's
  provenance->overrides = earlier.overrides;
  provenance->overrides.insert(provenance->overrides.end(), opt.overrides.begin(),
                               opt.overrides.end());
  for (const std::string& change : changed_inputs(earlier.inputs)) {
    std::cerr << "pamsim: warning: " << change << " since the run in " << opt.from
              << "; its outputs may differ\n";
  }
  const BuildInfo now = build_info();
  if (earlier.pamsim_version != now.pamsim_version || earlier.git_commit != now.git_commit) {
    std::cerr << "pamsim: warning: " << opt.from << " was made by pamsim " << earlier.pamsim_version
              << " (" << earlier.git_commit << "), this is " << now.pamsim_version << " ("
              << now.git_commit
              << "); its outputs may differ where the physics or defaults changed\n";
  }
  // a live trial's changes that no scenario can hold (pamsim view --record)
  for (const std::string& line : unreproduced_live_changes(opt.from)) {
    std::cerr << "pamsim: warning: " << line << "\n";
  }
  if (!opt.trials_given) opt.trials = static_cast<int>(earlier.seeds.size());
  return (fs::path(opt.from) / kResolvedScenarioFile).string();
}

// --video FILE, checked before anything runs (a single trial, a file, the GL backend)
VideoOptions video_options_of(const RunOptions& opt) {
  VideoOptions video;
  if (opt.video.empty()) return video;
  if (opt.trials != 1) {
    throw InputError("--video renders a single trial; drop --trials " + std::to_string(opt.trials) +
                     " (or use pamsim render)");
  }
  if (opt.video == "-") {
    throw InputError(
        "--video -: run prints its summary on standard output; give a file (or "
        "pamsim render -o - for the video alone)");
  }
  video.mp4_path = opt.video;
  refuse_existing_file(video.mp4_path, opt.force);
  video.backend = choose_gl_backend("");
  if (video.backend == GlBackend::kEgl) video.egl_device = choose_egl_device(-1);
  validate_video_options(video, "--video");
  return video;
}

std::vector<TrialResult> run_trials_of(const RunOptions& opt, const TrialModel& model,
                                       const Scenario& sc, int threads, const VideoOptions& video,
                                       ControlLog* control_log) {
  if (opt.readings) {
    // the one trial, its controller's inputs logged at every tick
    TrialOptions options;
    options.control_log = control_log;
    return {run_trial(model, sc, sc.seed, options)};
  }
  if (!opt.video.empty()) {
    // the same trial as run_trials' first, watched by the renderer
    return {run_rendered_trial(model, sc, sc.seed, video, true).trial};
  }
  // a bar for several trials (one is over in a blink)
  ProgressReporter progress("pamsim run", opt.trials, 0, std::cerr,
                            opt.trials > 1 ? progress_style(opt.quiet) : ProgressStyle::kQuiet);
  std::vector<TrialResult> results =
      run_trials(model, sc, opt.trials, threads, true, [&](int done) { progress.update(done); });
  progress.finish(opt.trials);
  return results;
}

// The trials' outputs into the staging folder; returns the summary printed on stdout.
nlohmann::json write_run_outputs(const StagedOutputs& staged,
                                 const std::vector<TrialResult>& results, const Scenario& sc,
                                 bool plots) {
  if (results.size() == 1) {
    const TrialResult& r = results.front();
    write_trial_outputs(staged.staging(), r, sc);
    if (plots) write_angle_plot(staged.path(trial_plot_name(r.trajectory)), r, sc);
    return summary_to_json(r.summary, sc, false);
  }
  std::vector<TrialSummary> summaries;
  std::vector<const Trajectory*> trajectories;
  for (const auto& r : results) {
    char name[32];
    std::snprintf(name, sizeof(name), "trial_%04d", static_cast<int>(r.summary.seed - sc.seed));
    write_trial_outputs(staged.path(name), r, sc);
    summaries.push_back(r.summary);
    trajectories.push_back(&r.trajectory);
  }
  nlohmann::json printed = aggregate_summaries(summaries, sc);
  write_file_atomically(staged.path("summary.json"), printed.dump(2) + "\n");
  if (plots) write_angle_band_plot(staged.path("angle_band.png"), trajectories, sc);
  return printed;
}

// --out, or renders/<scenario name>..., or DIR_rerun with --from DIR
std::string out_dir_of(const RunOptions& opt) {
  if (!opt.out.empty()) return opt.out;
  if (!opt.from.empty()) return fs::path(opt.from).lexically_normal().string() + "_rerun";
  return default_out_dir(opt.scenario, opt.overrides);
}

// the comment heading a run's scenario.toml
std::string resolved_header(const Provenance& provenance) {
  return "# The scenario of a pamsim run, resolved by pamsim " PAMSIM_VERSION " from " +
         provenance.scenario_file +
         "\n# (provenance.json beside it says how); pamsim run --from "
         "<this folder> runs it again\n";
}

// --trials N (>= 1), and --readings of one trial without a video
void check_trial_count(const RunOptions& opt) {
  if (opt.trials < 1) throw InputError("--trials must be >= 1, got " + std::to_string(opt.trials));
  if (opt.readings && (opt.trials != 1 || !opt.video.empty())) {
    throw InputError("--readings writes one trial's readings: drop --trials and --video");
  }
}

// readings.csv: the controller's inputs at every tick, with the model's muscle labels
void write_readings(const StagedOutputs& staged, const TrialModel& model, const ControlLog& log) {
  std::vector<std::string> labels;
  for (const BoundMuscle& m : model.muscles) labels.push_back(m.label);
  write_readings_csv(staged.path("readings.csv"), labels, log);
}

void run(RunOptions opt) {
  const auto started = std::chrono::steady_clock::now();
  Provenance provenance;
  provenance.command = "run";
  provenance.started_utc = utc_timestamp();
  provenance.overrides = opt.overrides;
  std::string scenario_path = opt.scenario;  // the file read
  if (!opt.from.empty()) {
    scenario_path = take_earlier_run(opt, &provenance);
  } else {
    if (opt.scenario.empty()) throw InputError("run needs a scenario file, or --from DIR");
    provenance.scenario_file = opt.scenario;
  }
  check_trial_count(opt);
  const int threads = resolve_thread_count(opt.threads);
  provenance.threads = opt.video.empty() ? std::min(threads, opt.trials) : 1;
  const VideoOptions video = video_options_of(opt);
  const std::string out = out_dir_of(opt);
  // read once: the scenario, its resolved text (paths relative to the output folder) and
  // its input files, whatever happens to the file meanwhile
  RecordedScenario recorded =
      load_recorded_scenario(read_text_file(scenario_path), scenario_path, opt.overrides, out,
                             resolved_header(provenance));
  Scenario& sc = recorded.scenario;
  provenance.inputs = fingerprint_inputs(recorded.input_paths);
  // a rerun's summary names the scenario file the first run was given, as that run's did
  if (!opt.from.empty()) sc.path = provenance.scenario_file;
  const TrialModel model = load_trial_model(sc);
  if (!opt.video.empty()) check_camera(model.model.get(), model.model_path, video.camera);
  if (!opt.force) refuse_earlier_outputs(out, kRunOutputs);
  use_plot_formats(opt.plot_format);
  const bool plots = plots_wanted(opt.no_plot);
  // every output is written into a staging folder and published together at the end: a
  // failure half way leaves the folder as it was (made only once every input is good)
  StagedOutputs staged(out, kRunOutputs);
  ControlLog control_log;
  const std::vector<TrialResult> results =
      run_trials_of(opt, model, sc, threads, video, &control_log);
  for (const TrialResult& r : results) {
    provenance.seeds.push_back(r.summary.seed);
    provenance.trials.push_back(timing_of(r.summary));
  }
  nlohmann::json printed;
  staged.write([&] {
    printed = write_run_outputs(staged, results, sc, plots);
    if (opt.readings) write_readings(staged, model, control_log);
    write_file_atomically(staged.path(kResolvedScenarioFile), recorded.resolved_toml);
    write_provenance(staged.path(kProvenanceFile), provenance, started);
  });
  staged.publish();
  std::cout << printed.dump(2) << "\n";
  std::cerr << "pamsim: outputs in " << out << "\n";
  warn_if_the_start_moved(sc, results);
  warn_if_a_line_breaks(sc, results);
  if (report_diverged(sc, results) > 0) throw SimulationFailed();
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto opt = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Run a scenario: one trial, or --trials N in parallel");
  cmd->add_option("scenario", opt->scenario, "Scenario file (TOML)");
  cmd->add_option("--from", opt->from,
                  "Run an earlier run's scenario.toml again (its folder), with its trial count");
  add_overrides_option(cmd, &opt->overrides, "Override a scenario key: --set reflex.v_thr_mm_s=60");
  cmd->add_option("--out", opt->out,
                  "Output folder (default renders/<scenario name>[__<key>-<value> per --set], "
                  "or DIR_rerun with --from DIR)");
  CLI::Option* trials =
      cmd->add_option("--trials", opt->trials, "Number of trials, seeds seed..seed+N-1")
          ->capture_default_str();
  cmd->add_option("--threads", opt->threads, "Worker threads (0: all cores)")
      ->capture_default_str();
  cmd->add_option("--video", opt->video,
                  "Also render the trial to this MP4 (1280x720, 30 fps; see pamsim render)");
  cmd->add_flag("--force", opt->force, "Replace the outputs of an earlier run in the folder");
  cmd->add_flag("--no-plot", opt->no_plot, "Write no plots (gnuplot not needed)");
  cmd->add_flag("--quiet", opt->quiet, "No progress bar or progress lines (--trials N)");
  cmd->add_flag("--readings", opt->readings,
                "Also write readings.csv: the controller's inputs at every tick, lossless "
                "(pamsim controller replay)");
  add_plot_format_option(cmd, &opt->plot_format);
  cmd->callback([opt, trials] {
    RunOptions o = *opt;
    o.trials_given = trials->count() > 0;
    run(o);
  });
}

}  // namespace pamsim
