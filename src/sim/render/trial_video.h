// trial_video.h: a trial's video, made while the trial runs. A TrialObserver that, at each
// frame time k / fps (k = 0 .. ceil(duration * fps) - 1), draws the model from one of its
// cameras, writes the trial's numbers on top (time, the joint, every muscle's chamber
// pressure with its command, reflex state) and optionally live plots of the joint and the
// pressures in the bottom-left corner, and streams the frame to an MP4 and/or a PNG
// sequence. Nothing appears at the output paths before finish(). What `pamsim render` and
// `pamsim run --video` use.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "pam_actuator/chou_hannaford.h"
#include "sim/core/scenario.h"
#include "sim/core/trial.h"
#include "sim/core/trial_model.h"
#include "sim/render/gl_context.h"
#include "sim/render/mp4_writer.h"
#include "sim/render/png_sequence_writer.h"
#include "sim/render/scene_renderer.h"
#include "sim/render/trial_scene.h"

namespace pamsim {

inline constexpr int kMaxVideoFps = 240;

struct VideoOptions {
  std::string mp4_path;  // H.264 MP4 file (.mp4); empty: none
  std::string png_dir;   // folder for frame_00000.png, ...; empty: none
  int width_px = 1280;   // even (4:2:0 video), [kMinFrameSidePx, kMaxFrameSidePx]
  int height_px = 720;
  int fps = 30;  // [1, kMaxVideoFps]
  RenderQuality quality = RenderQuality::kDefault;
  std::string x264_preset;  // libx264's speed/size trade-off; empty: by quality (fast:
                            // ultrafast, default: veryfast); one of kX264Presets
  std::string camera = "side";
  GlBackend backend = GlBackend::kOsmesa;
  EglDeviceChoice egl_device;  // egl only
  bool plot = false;           // live plots of angle and pressures
  // called after each frame written with (frames written, frames in all), e.g. for progress
  std::function<void(long, long)> on_frame;
};

// The printf format of a live plot's time labels at `grid_lines` lines over [0, duration_s]:
// the fewest decimals (0-3) that tell the labels apart ("%.0f" for 3 s, "%.1f" for 1.2 s,
// "%.2f" for 0.15 s, whose "%.1f" would read 0 0.1 0.1 0.2).
std::string figure_time_format(double duration_s, int grid_lines);

// libx264's presets, fastest first (what --preset accepts).
inline constexpr const char* kX264Presets[] = {
    "ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow"};

// Checks what needs no model: size, fps, the outputs' names. `mp4_option` names the option
// that gave mp4_path in messages ("-o", "--video"). Throws InputError naming the option.
void validate_video_options(const VideoOptions& options, const std::string& mp4_option);

class TrialVideo : public TrialObserver {
 public:
  // Sets up rendering of `model` (the camera is checked against it) and opens the
  // outputs as temp files. Throws InputError (see validate_video_options, SceneRenderer,
  // Mp4Writer, PngSequenceWriter); `options` are expected to be validated already.
  // `seed` is the trial's (for the title line).
  TrialVideo(const TrialModel& model, const Scenario& scenario, const VideoOptions& options,
             std::uint64_t seed);
  ~TrialVideo() override;  // unfinished outputs are removed

  double next_observation_time_s() const override;
  void observe(const TrialSnapshot& snapshot) override;

  // Completes the outputs and puts them in place.
  void finish();

  long frames_written() const { return next_frame_; }
  std::string encoder_name() const;  // the MP4's H.264 encoder; "png" without an MP4
  std::string gl_in_use() const { return renderer_.gl_in_use(); }  // SceneRenderer's

 private:
  struct Plots;
  void draw_overlays(const TrialSnapshot& snapshot);
  // each live plot's height [px] below a table of `table_rows` rows
  int plot_height_px(std::size_t table_rows) const;

  VideoOptions options_;
  std::string title_;        // "drop_mass.toml, seed 1"
  double trigger_s_ = -1.0;  // the first reflex trigger; < 0: none yet
  std::string plot_key_;     // "red ago, blue anta": the pressure plot's lines
  long frame_count_ = 0;     // frames the whole trial makes
  long next_frame_ = 0;
  TrialScene scene_;
  SceneRenderer& renderer_;       // scene_'s, for the overlays
  std::unique_ptr<Plots> plots_;  // with --plot
  std::unique_ptr<Mp4Writer> mp4_;
  std::unique_ptr<PngSequenceWriter> png_;
};

struct RenderedTrial {
  TrialResult trial;
  long frames = 0;      // written to each output
  std::string encoder;  // the MP4's H.264 encoder; "png" without an MP4
  std::string gl;       // the GL context that drew it (SceneRenderer::gl_in_use)
};

// Runs `scenario`'s trial with `seed` on `model`, rendered as it runs into the outputs of
// `options` (validated), which are complete and in place on return. Throws as TrialVideo.
RenderedTrial run_rendered_trial(const TrialModel& model, const Scenario& scenario,
                                 std::uint64_t seed, const VideoOptions& options,
                                 bool keep_trajectory);

}  // namespace pamsim
