// render.cc: `pamsim render SCENARIO.toml [--set key=value ...] [-o FILE.mp4]
// [--png-dir DIR] [--width W] [--height H] [--fps F] [--quality fast|default] [--preset P]
// [--camera NAME] [--backend osmesa|egl] [--gpu N] [--plot] [--force]`: runs the scenario's trial
// (its own seed) and renders it headlessly while it runs (TrialVideo): H.264 MP4 (default
// renders/<scenario>/<scenario>.mp4) and/or numbered PNGs, saying which GL renderer drew it.
// The physics is the same as `pamsim run`'s, bit for bit.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "base/input_error.h"
#include "sim/cli/cli_options.h"
#include "sim/cli/commands.h"
#include "sim/cli/progress.h"
#include "sim/core/runner.h"
#include "sim/io/outputs.h"
#include "sim/scenario/scenario_file.h"
#include "sim/io/staged_outputs.h"
#include "sim/render/trial_video.h"

namespace pamsim {
namespace {

struct RenderCommandOptions {
  std::string scenario;
  std::vector<std::string> overrides;
  VideoOptions video;
  std::string quality = "default";
  std::string backend;  // empty: $MUJOCO_GL, $PAMSIM_GL_BACKEND, else osmesa
  int gpu = -1;         // EGL device; -1: $EGL_DEVICE_ID, else the first GPU
  bool force = false;   // replace an existing MP4 or PNG frames
  bool quiet = false;
};

void render(RenderCommandOptions opt) {
  // everything that needs no model is checked before the trial is loaded
  VideoOptions& video = opt.video;
  video.quality = parse_render_quality(opt.quality);
  video.backend = choose_gl_backend(opt.backend);
  if (video.backend == GlBackend::kEgl) {
    video.egl_device = choose_egl_device(opt.gpu);
  } else if (opt.gpu != -1) {  // (a device in the environment does not concern osmesa)
    throw InputError("--gpu " + std::to_string(opt.gpu) +
                     " chooses an EGL device, but the backend is osmesa: add --backend egl");
  }
  if (video.mp4_path.empty() && video.png_dir.empty()) {
    const std::string name = std::filesystem::path(opt.scenario).stem().string();
    video.mp4_path = "renders/" + name + "/" + name + ".mp4";
  }
  validate_video_options(video, "-o");
  if (!video.mp4_path.empty()) refuse_existing_file(video.mp4_path, opt.force);
  if (!video.png_dir.empty() && !opt.force) {
    refuse_earlier_outputs(video.png_dir, {"frame_[0-9][0-9][0-9][0-9][0-9]*.png"});
  }
  const Scenario sc = load_scenario(opt.scenario, opt.overrides);
  const TrialModel model = load_trial_model(sc);

  // the trial, rendered as it runs; the time includes setting up GL and the encoder
  const auto start = std::chrono::steady_clock::now();
  std::unique_ptr<ProgressReporter> progress;
  video.on_frame = [&](long done, long total) {
    if (!progress) {
      progress = std::make_unique<ProgressReporter>("pamsim render", total, 0, std::cerr,
                                                    progress_style(opt.quiet), "frames");
    }
    progress->update(done);
  };
  const RenderedTrial r = run_rendered_trial(model, sc, sc.seed, video, false);
  if (progress) progress->finish(r.frames);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const std::string where = video.mp4_path.empty() ? video.png_dir + "/" : video.mp4_path;
  std::cerr << "pamsim: GL: " << r.gl << "\n";
  char took[64];  // to sensible digits: "8.94 s, 5.37 frames/s"
  std::snprintf(took, sizeof(took), "%.3g s, %.3g frames/s", wall_s, r.frames / wall_s);
  std::cerr << "pamsim: " << where << ": " << r.frames << " frames of " << video.width_px << "x"
            << video.height_px << " at " << video.fps << " fps (" << r.encoder << ") in " << took
            << "\n";
  const TrialSummary& s = r.trial.summary;
  if (s.status != "ok") {
    std::cerr << "pamsim: " << sc.path << ": trial with seed " << s.seed << " " << s.status << ": "
              << s.message << "\n";
    throw SimulationFailed();
  }
}

}  // namespace

void add_render_command(CLI::App& app) {
  const auto [cmd, opt] = add_command<RenderCommandOptions>(
      app, "render",
      "Render a scenario's trial to H.264 MP4 and/or PNGs (no display or GPU needed)", render);
  VideoOptions& v = opt->video;
  cmd->add_option("scenario", opt->scenario, "Scenario file (TOML)")->required();
  add_overrides_option(cmd, &opt->overrides, "Override a scenario key: --set sim.duration_s=2");
  cmd->add_option("-o,--output", v.mp4_path,  // "-": a fragmented MP4 on standard output
                  "MP4 file, - for standard output (fragmented MP4; default "
                  "renders/<scenario>/<scenario>.mp4 unless --png-dir alone)");
  cmd->add_option("--png-dir", v.png_dir, "Also (or only) write frame_00000.png, ... here");
  cmd->add_option("--width", v.width_px, "Frame width in pixels, even")->capture_default_str();
  cmd->add_option("--height", v.height_px, "Frame height in pixels, even")->capture_default_str();
  cmd->add_option("--fps", v.fps, "Frames per second of simulated time")->capture_default_str();
  cmd->add_option("--quality", opt->quality,
                  "fast (no shadows, reflections, skybox, multisampling) or default (the model's)")
      ->capture_default_str();
  cmd->add_option("--preset", v.x264_preset,
                  "libx264's speed/size trade-off: ultrafast ... veryslow (default: ultrafast "
                  "with --quality fast, else veryfast)");
  cmd->add_option("--camera", v.camera, "A camera named in the model")->capture_default_str();
  cmd->add_option(
      "--backend", opt->backend,
      "GL context: osmesa or egl (default $PAMSIM_GL_BACKEND, else $MUJOCO_GL when "
      "egl or osmesa, else osmesa); egl falls back to osmesa where EGL gives no context");
  cmd->add_option("--gpu", opt->gpu,
                  "EGL device number, with --backend egl (default $EGL_DEVICE_ID, else the "
                  "first GPU, else Mesa's software renderer)");
  cmd->add_flag("--plot", v.plot, "Live plots of angle and pressures, bottom left");
  cmd->add_flag("--force", opt->force, "Replace an existing MP4, or the PNG frames in --png-dir");
  cmd->add_flag("--quiet", opt->quiet, "No progress bar or progress lines");
}

}  // namespace pamsim
