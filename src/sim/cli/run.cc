// run.cc: `pamsim run SCENARIO.toml [--set key=value ...] [--out DIR] [--trials N]
// [--threads T] [--video FILE.mp4]`: one trial (outputs in DIR, and with --video its video,
// rendered as in `pamsim render` with the default settings) or N trials (DIR/trial_<seed>/
// each, plus the aggregate DIR/summary.json and the angle band plot; no video).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "pam_actuator/atomic_file.h"
#include "pam_actuator/input_error.h"
#include "sim/cli/commands.h"
#include "sim/core/runner.h"
#include "sim/io/outputs.h"
#include "sim/io/plot.h"
#include "sim/io/scenario_file.h"
#include "sim/io/staged_outputs.h"
#include "sim/render/scene_renderer.h"
#include "sim/render/trial_video.h"

namespace pamsim {
namespace {

struct RunOptions {
  std::string scenario;
  std::vector<std::string> overrides;
  std::string out;
  int trials = 1;
  int threads = 0;
  std::string video;  // MP4 of the single trial
};

std::string default_out_dir(const std::string& scenario) {
  return "renders/" + std::filesystem::path(scenario).stem().string();
}

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

void run(const RunOptions& opt) {
  if (opt.trials < 1) throw InputError("--trials must be >= 1, got " + std::to_string(opt.trials));
  const int threads = resolve_thread_count(opt.threads);
  VideoOptions video;
  if (!opt.video.empty()) {
    if (opt.trials != 1) {
      throw InputError("--video renders a single trial; drop --trials " +
                       std::to_string(opt.trials) + " (or use pamsim render)");
    }
    video.mp4_path = opt.video;
    video.backend = choose_gl_backend("");
    if (video.backend == GlBackend::kEgl) video.egl_device = choose_egl_device(-1);
    validate_video_options(video, "--video");
  }
  const Scenario sc = load_scenario(opt.scenario, opt.overrides);
  const TrialModel model = load_trial_model(sc);
  if (!opt.video.empty()) check_camera(model.model.get(), model.model_path, video.camera);
  const std::string out = opt.out.empty() ? default_out_dir(opt.scenario) : opt.out;
  // every output is written into a staging folder and published together at the end: a
  // failure half way leaves the folder as it was (made only once every input is good)
  StagedOutputs staged(out, {"trajectory.csv", "summary.json", "angle.png", "position.png",
                             "angle_band.png", "trial_[0-9][0-9][0-9][0-9]"});
  std::vector<TrialResult> results;
  if (opt.video.empty()) {
    results = run_trials(model, sc, opt.trials, threads);
  } else {
    // the same trial as run_trials' first, watched by the renderer
    results.push_back(run_rendered_trial(model, sc, sc.seed, video, true).trial);
  }

  nlohmann::json printed;
  staged.write([&] {
    if (opt.trials == 1) {
      const TrialResult& r = results.front();
      write_trial_outputs(staged.staging(), r, sc);
      write_angle_plot(staged.path(trial_plot_name(r.trajectory)), r, sc);
      printed = summary_to_json(r.summary, sc);
    } else {
      std::vector<TrialSummary> summaries;
      std::vector<const Trajectory*> trajectories;
      for (const auto& r : results) {
        char name[32];
        std::snprintf(name, sizeof(name), "trial_%04d", static_cast<int>(r.summary.seed - sc.seed));
        write_trial_outputs(staged.path(name), r, sc);
        summaries.push_back(r.summary);
        trajectories.push_back(&r.trajectory);
      }
      printed = aggregate_summaries(summaries, sc);
      write_file_atomically(staged.path("summary.json"), printed.dump(2) + "\n");
      write_angle_band_plot(staged.path("angle_band.png"), trajectories, sc);
    }
  });
  staged.publish();
  std::cout << printed.dump(2) << "\n";
  std::cerr << "pamsim: outputs in " << out << "\n";
  if (report_diverged(sc, results) > 0) throw SimulationFailed();
}

}  // namespace

void add_run_command(CLI::App& app) {
  auto opt = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Run a scenario: one trial, or --trials N in parallel");
  cmd->add_option("scenario", opt->scenario, "Scenario file (TOML)")->required();
  cmd->add_option("--set", opt->overrides, "Override a scenario key: --set reflex.v_thr_mm_s=60")
      ->take_all();
  cmd->add_option("--out", opt->out, "Output folder (default renders/<scenario name>)");
  cmd->add_option("--trials", opt->trials, "Number of trials, seeds seed..seed+N-1");
  cmd->add_option("--threads", opt->threads, "Worker threads (default: all cores)");
  cmd->add_option("--video", opt->video,
                  "Also render the trial to this MP4 (1280x720, 30 fps; see pamsim render)");
  cmd->callback([opt] { run(*opt); });
}

}  // namespace pamsim
