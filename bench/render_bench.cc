// render_bench.cc: headless trial video on the drop-mass scenario, on the GL backend the
// environment chooses (MUJOCO_GL=osmesa|egl, EGL_DEVICE_ID; default OSMesa, llvmpipe), one
// backend per process: run it once per backend to compare them (a GPU with MUJOCO_GL=egl):
//   BM_RenderTrial/640x480/fast       end to end: GL and encoder set-up, the 3 s trial
//                                     simulated, 90 frames rendered at 30 fps and encoded to
//                                     an MP4 (ultrafast); the issue asks >= 60 frames/s
//   BM_RenderTrial/1280x720/default   the same with the model's own visual settings (shadows,
//                                     reflections, 4x multisampling; veryfast): compare with
//                                     MuJoCo's `record` sample on the same model and size
//   BM_DrawFrame/...                  the share of one frame's drawing and pixel read-back
//   BM_EncodeFrame/...                colour conversion and H.264 alone: the frame rate the
//                                     encoding thread sustains
//   BM_FrameVsMujoco/...              pamsim's frame against bare MuJoCo's in one run (issue
//                                     46): counter pamsim_over_mujoco, the ratio of their
//                                     frame rates; /geom_backdrop draws the backdrop the slow
//                                     way, as 0.4 did (about 0.5 at 720p on llvmpipe)
// Counter frames_per_s: frames / wall seconds (real time: llvmpipe and x264 run threads).
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "sim/render/mp4_writer.h"
#include "sim/core/runner.h"
#include "sim/scenario/scenario_file.h"
#include "sim/render/scene_renderer.h"
#include "sim/render/trial_video.h"

namespace pamsim {
namespace {

constexpr int kFps = 30;

// The EGL device the environment asks for, for the egl backend.
EglDeviceChoice egl_device_for(GlBackend backend) {
  return backend == GlBackend::kEgl ? choose_egl_device(-1) : EglDeviceChoice{};
}

Scenario drop_mass() {
  return load_scenario(std::string(PAMSIM_SOURCE_DIR) + "/scenarios/drop_mass.toml");
}

std::string temp_mp4() { return "/tmp/pamsim_render_bench_" + std::to_string(::getpid()) + ".mp4"; }

void BM_RenderTrial(benchmark::State& state, int width, int height, RenderQuality quality) {
  const Scenario sc = drop_mass();
  const TrialModel arm = load_trial_model(sc);
  VideoOptions video;
  video.mp4_path = temp_mp4();
  video.width_px = width;
  video.height_px = height;
  video.fps = kFps;
  video.quality = quality;
  video.backend = choose_gl_backend("");
  video.egl_device = egl_device_for(video.backend);
  long frames = 0;
  for (auto _ : state) {
    const RenderedTrial r = run_rendered_trial(arm, sc, sc.seed, video, false);
    frames = r.frames;
    state.SetLabel(r.gl);
    if (r.trial.summary.status != "ok") state.SkipWithError("trial diverged");
  }
  std::remove(video.mp4_path.c_str());
  state.counters["frames"] = static_cast<double>(frames);
  state.counters["frames_per_s"] = benchmark::Counter(
      static_cast<double>(frames), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK_CAPTURE(BM_RenderTrial, 640x480 / fast, 640, 480, RenderQuality::kFast)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);
BENCHMARK_CAPTURE(BM_RenderTrial, 1280x720 / default, 1280, 720, RenderQuality::kDefault)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(10.0);

// the arm at its start angle (what is drawn costs about the same in every state)
MjDataPtr start_state(const TrialModel& arm, const Scenario& sc) {
  MjDataPtr data = make_data(arm.model.get());
  data->qpos[arm.joint.qpos] = sc.start_position;
  mj_forward(arm.model.get(), data.get());
  return data;
}

void BM_DrawFrame(benchmark::State& state, int width, int height, RenderQuality quality) {
  const Scenario sc = drop_mass();
  const TrialModel arm = load_trial_model(sc);
  const MjDataPtr data = start_state(arm, sc);
  SceneRenderer renderer(arm.model.get(), arm.model_path,
                         SceneRenderOptions{width, height, quality, "side", choose_gl_backend(""),
                                            egl_device_for(choose_gl_backend(""))});
  for (auto _ : state) {
    renderer.draw_scene(data.get());
    renderer.draw_text("time", "1.200 s");
    benchmark::DoNotOptimize(renderer.read_pixels());
  }
  state.counters["frames_per_s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK_CAPTURE(BM_DrawFrame, 640x480 / fast, 640, 480, RenderQuality::kFast)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_DrawFrame, 1280x720 / default, 1280, 720, RenderQuality::kDefault)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_EncodeFrame(benchmark::State& state, int width, int height, const char* preset) {
  // a rendered frame: the encoder's work depends on the picture
  const Scenario sc = drop_mass();
  const TrialModel arm = load_trial_model(sc);
  const MjDataPtr data = start_state(arm, sc);
  std::vector<unsigned char> rgb;
  {
    SceneRenderer renderer(
        arm.model.get(), arm.model_path,
        SceneRenderOptions{width, height, RenderQuality::kFast, "side", choose_gl_backend(""),
                           egl_device_for(choose_gl_backend(""))});
    renderer.draw_scene(data.get());
    const unsigned char* pixels = renderer.read_pixels();
    rgb.assign(pixels, pixels + 3 * static_cast<std::size_t>(width) * height);
  }
  Mp4Settings settings;
  settings.width_px = width;
  settings.height_px = height;
  settings.fps = kFps;
  settings.x264_preset = preset;
  const std::string path = temp_mp4();
  {
    Mp4Writer writer(path, settings);
    for (auto _ : state) writer.write_frame(rgb.data());
    writer.finish();
  }
  std::remove(path.c_str());
  state.counters["frames_per_s"] =
      benchmark::Counter(1.0, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK_CAPTURE(BM_EncodeFrame, 640x480 / ultrafast, 640, 480, "ultrafast")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_EncodeFrame, 1280x720 / veryfast, 1280, 720, "veryfast")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// MuJoCo on its own, as its `record` sample draws a frame: mjv_updateScene, mjr_render, a
// time stamp (mjr_overlay), mjr_readPixels; the model's own look (its floor, no backdrop),
// at the size, camera and quality pamsim is asked for, in a GL context of its own.
class BareMujocoFrame {
 public:
  BareMujocoFrame(const mjModel* model, const SceneRenderOptions& o)
      : gl_(create_gl_context(o.backend, o.width_px, o.height_px, o.egl_device)),
        model_(mj_copyModel(nullptr, model)),
        rgb_(3 * static_cast<std::size_t>(o.width_px) * o.height_px) {
    model_->vis.global.offwidth = o.width_px;
    model_->vis.global.offheight = o.height_px;
    if (o.quality == RenderQuality::kFast) model_->vis.quality.offsamples = 0;
    mjv_defaultOption(&option_);
    mjv_defaultCamera(&camera_);
    camera_.type = mjCAMERA_FIXED;
    camera_.fixedcamid = mj_name2id(model_.get(), mjOBJ_CAMERA, o.camera.c_str());
    mjv_defaultScene(&scene_);
    mjv_makeScene(model_.get(), &scene_, 2000);
    if (o.quality == RenderQuality::kFast) {
      scene_.flags[mjRND_SHADOW] = scene_.flags[mjRND_REFLECTION] = scene_.flags[mjRND_SKYBOX] = 0;
    }
    mjr_defaultContext(&context_);
    mjr_makeContext(model_.get(), &context_, mjFONTSCALE_150);
    mjr_setBuffer(mjFB_OFFSCREEN, &context_);
    viewport_ = {0, 0, o.width_px, o.height_px};
  }
  ~BareMujocoFrame() {
    gl_->make_current();
    mjr_freeContext(&context_);
    mjv_freeScene(&scene_);
  }
  void draw(const mjData* data) {
    gl_->make_current();
    mjv_updateScene(model_.get(), const_cast<mjData*>(data), &option_, nullptr, &camera_, mjCAT_ALL,
                    &scene_);
    mjr_render(viewport_, &scene_, &context_);
    mjr_overlay(mjFONT_NORMAL, mjGRID_TOPLEFT, viewport_, "Time = 1.200", nullptr, &context_);
    mjr_readPixels(rgb_.data(), nullptr, viewport_, &context_);
    benchmark::DoNotOptimize(rgb_.data());
  }

 private:
  std::unique_ptr<GlContext> gl_;
  MjModelPtr model_;
  std::vector<unsigned char> rgb_;
  mjvOption option_;
  mjvCamera camera_;
  mjvScene scene_;
  mjrContext context_;
  mjrRect viewport_;
};

// pamsim's frame as TrialVideo draws it: the state, two muscles as capsules, the backdrop,
// two text tables, two live plots, the read-back.
void draw_pamsim_frame(SceneRenderer* renderer, const mjData* data, mjvFigure* figure) {
  const float teal[4] = {0.1f, 0.5f, 0.5f, 1.0f};
  SceneRenderer::Capsule ago{{-0.40, 0, 1.025}, {-0.20, 0, 1.025}, 0.008, {}};
  SceneRenderer::Capsule anta{{-0.40, 0, 0.975}, {-0.20, 0, 0.975}, 0.009, {}};
  std::copy(teal, teal + 4, ago.rgba);
  std::copy(teal, teal + 4, anta.rgba);
  renderer->draw_scene(data, {ago, anta});
  renderer->draw_text("time\nangle\nago\nanta\nreflex",
                      "1.200 s\n-42.67 deg\n0.409 MPa\n0.398 MPa\nago (first trigger 1.19 s)");
  renderer->draw_text("trial\nmuscle colour", "drop_mass.toml, seed 1\ndark 0 to yellow",
                      mjGRID_TOPRIGHT);
  const int w = renderer->width_px() / 3;
  const int h = renderer->height_px() / 4;
  renderer->draw_figure(mjrRect{0, 0, w, h}, figure);
  renderer->draw_figure(mjrRect{0, h, w, h}, figure);
  benchmark::DoNotOptimize(renderer->read_pixels());
}

void BM_FrameVsMujoco(benchmark::State& state, int width, int height, RenderQuality quality,
                      bool backdrop_geom) {
  const Scenario sc = drop_mass();
  const TrialModel arm = load_trial_model(sc);
  const MjDataPtr data = start_state(arm, sc);
  SceneRenderOptions options{
      width, height, quality, "side", choose_gl_backend(""), egl_device_for(choose_gl_backend(""))};
  options.backdrop_geom = backdrop_geom;
  SceneRenderer renderer(arm.model.get(), arm.model_path, options);
  BareMujocoFrame mujoco(arm.model.get(), options);
  mjvFigure figure;
  mjv_defaultFigure(&figure);
  for (int i = 0; i < 90; ++i) {
    figure.linedata[0][2 * i] = static_cast<float>(i) / 30.0f;
    figure.linedata[0][2 * i + 1] = static_cast<float>(i % 7);
  }
  figure.linepnt[0] = 90;
  // one frame each per iteration, alternating: both sides see the same machine
  using Clock = std::chrono::steady_clock;
  double pamsim_s = 0.0, mujoco_s = 0.0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    draw_pamsim_frame(&renderer, data.get(), &figure);
    const auto t1 = Clock::now();
    mujoco.draw(data.get());
    const auto t2 = Clock::now();
    pamsim_s += std::chrono::duration<double>(t1 - t0).count();
    mujoco_s += std::chrono::duration<double>(t2 - t1).count();
    state.SetIterationTime(std::chrono::duration<double>(t1 - t0).count());
  }
  const double frames = static_cast<double>(state.iterations());
  state.counters["pamsim_frames_per_s"] = frames / pamsim_s;
  state.counters["mujoco_frames_per_s"] = frames / mujoco_s;
  state.counters["pamsim_over_mujoco"] = mujoco_s / pamsim_s;
}
BENCHMARK_CAPTURE(BM_FrameVsMujoco, 1280x720 / default, 1280, 720, RenderQuality::kDefault, false)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(3.0);
BENCHMARK_CAPTURE(BM_FrameVsMujoco, 1280x720 / default / geom_backdrop, 1280, 720,
                  RenderQuality::kDefault, true)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(3.0);
BENCHMARK_CAPTURE(BM_FrameVsMujoco, 640x480 / fast, 640, 480, RenderQuality::kFast, false)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(2.0);

}  // namespace
}  // namespace pamsim
