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
// Counter frames_per_s: frames / wall seconds (real time: llvmpipe and x264 run threads).
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <cstdio>
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

std::string temp_mp4() {
  return "/tmp/pamsim_render_bench_" + std::to_string(::getpid()) + ".mp4";
}

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
BENCHMARK_CAPTURE(BM_RenderTrial, 640x480/fast, 640, 480, RenderQuality::kFast)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(3.0);
BENCHMARK_CAPTURE(BM_RenderTrial, 1280x720/default, 1280, 720, RenderQuality::kDefault)
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
BENCHMARK_CAPTURE(BM_DrawFrame, 640x480/fast, 640, 480, RenderQuality::kFast)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_DrawFrame, 1280x720/default, 1280, 720, RenderQuality::kDefault)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_EncodeFrame(benchmark::State& state, int width, int height, const char* preset) {
  // a rendered frame: the encoder's work depends on the picture
  const Scenario sc = drop_mass();
  const TrialModel arm = load_trial_model(sc);
  const MjDataPtr data = start_state(arm, sc);
  std::vector<unsigned char> rgb;
  {
    SceneRenderer renderer(arm.model.get(), arm.model_path,
                           SceneRenderOptions{width, height, RenderQuality::kFast, "side",
                                              choose_gl_backend(""),
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
BENCHMARK_CAPTURE(BM_EncodeFrame, 640x480/ultrafast, 640, 480, "ultrafast")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_EncodeFrame, 1280x720/veryfast, 1280, 720, "veryfast")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace pamsim
