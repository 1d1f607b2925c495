// cli_render_test.cc: `pamsim render` and `pamsim run --video` as a user runs them on a
// machine without a display: the MP4 decodes (through libavformat) at the asked size with
// duration x fps frames, the trial in the video is the trial without video (same
// trajectory.csv, byte for byte), both GL backends and the PNG sequence work, and every bad
// input is one line on stderr, a non-zero exit, and no file or temp file left behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/cli_util.h"
#include "sim/video_decode.h"

namespace {

namespace fs = std::filesystem;
using pamsim_test::CliResult;
using pamsim_test::decode_video;
using pamsim_test::fresh_dir;
using pamsim_test::line_count;
using pamsim_test::read_file;
using pamsim_test::run_pamsim;

// No display, and no backend chosen by the environment, for every test here.
class CliRenderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* var :
         {"DISPLAY", "PAMSIM_GL_BACKEND", "MUJOCO_GL", "EGL_DEVICE_ID", "MUJOCO_EGL_DEVICE_ID"}) {
      ::unsetenv(var);
    }
  }
};

// Only the files named, nothing else (no temp file, no partial output).
void expect_exactly(const fs::path& dir, std::vector<std::string> names) {
  std::vector<std::string> found;
  for (const auto& e : fs::directory_iterator(dir)) found.push_back(e.path().filename().string());
  std::sort(found.begin(), found.end());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(found, names) << dir;
}

TEST_F(CliRenderTest, DropMassVideoDecodesWithDurationTimesFpsFrames) {
  const fs::path dir = fresh_dir("render_mp4");
  const std::string mp4 = (dir / "v.mp4").string();
  const CliResult r = run_pamsim("render scenarios/drop_mass.toml -o " + mp4 + " --fps 30");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto video = decode_video(mp4);
  ASSERT_TRUE(video.opened) << mp4;
  EXPECT_EQ(video.codec, "h264");
  EXPECT_EQ(video.width, 1280);
  EXPECT_EQ(video.height, 720);
  EXPECT_EQ(video.frames, 90) << "3 s x 30 fps";
  expect_exactly(dir, {"v.mp4"});
}

// The PAM leg renders with no code of its own: its eight muscles drawn
// as the arm's two, its own camera
TEST_F(CliRenderTest, TheLegsLandingRendersFromItsOwnCamera) {
  const fs::path dir = fresh_dir("render_leg");
  const std::string mp4 = (dir / "leg.mp4").string();
  const CliResult r = run_pamsim("render scenarios/landing.toml -o " + mp4 +
                                 " --width 320 --height 240 --quality fast --camera side");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto video = decode_video(mp4);
  ASSERT_TRUE(video.opened) << mp4;
  EXPECT_EQ(video.width, 320);
  EXPECT_EQ(video.frames, 45) << "1.5 s x 30 fps";
}

TEST_F(CliRenderTest, VideoDoesNotChangeTheTrial) {
  const fs::path dir = fresh_dir("render_physics");
  const std::string common = "run scenarios/drop_mass.toml --set sim.duration_s=1.5 --out ";
  const CliResult plain = run_pamsim(common + (dir / "plain").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  const CliResult filmed = run_pamsim(common + (dir / "filmed").string() + " --video " +
                                      (dir / "filmed" / "trial.mp4").string());
  ASSERT_EQ(filmed.exit_code, 0) << filmed.err;

  const std::string a = read_file(dir / "plain" / "trajectory.csv");
  const std::string b = read_file(dir / "filmed" / "trajectory.csv");
  ASSERT_GT(a.size(), 1000u);
  EXPECT_TRUE(a == b) << "trajectory.csv differs with --video";
  const auto video = decode_video((dir / "filmed" / "trial.mp4").string());
  EXPECT_EQ(video.frames, 45);
  expect_exactly(dir / "filmed", {"angle.png", "provenance.json", "scenario.toml", "summary.json",
                                  "trajectory.csv", "trial.mp4"});
}

// -o - streams a fragmented MP4 to standard output (into a pipe or a file), every frame in
// it; run --video - is refused (run's summary is on standard output).
TEST_F(CliRenderTest, DashStreamsTheVideoToStandardOutput) {
  const fs::path dir = fresh_dir("render_stdout");
  const fs::path piped = dir / "piped.mp4";
  const CliResult r = run_pamsim(
      "render scenarios/drop_mass.toml --quiet --width 160 --height 120 "
      "--quality fast --set sim.duration_s=0.5 drop.time_s=0.2 -o -",
      "bash -c '\"$0\" \"$@\" > " + piped.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto video = decode_video(piped.string());
  EXPECT_EQ(video.frames, 15);
  EXPECT_EQ(video.width, 160);
  expect_exactly(dir, {"piped.mp4"});  // no temp file, nothing named "-"
  const CliResult run =
      run_pamsim("run scenarios/drop_mass.toml --video - --out " + (dir / "r").string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(line_count(run.err), 1) << run.err;
}

// --preset trades encoding speed for size: the same frames, a smaller file from veryslow
TEST_F(CliRenderTest, PresetChoosesTheEncodersTradeOff) {
  const fs::path dir = fresh_dir("render_preset");
  std::uintmax_t bytes[2] = {0, 0};
  const char* presets[2] = {"ultrafast", "veryslow"};
  for (int i = 0; i < 2; ++i) {
    const fs::path mp4 = dir / (std::string(presets[i]) + ".mp4");
    const CliResult r = run_pamsim(
        "render scenarios/drop_mass.toml --quiet --width 320 --height 240 "
        "--set sim.duration_s=0.5 drop.time_s=0.2 --preset " +
        std::string(presets[i]) + " -o " + mp4.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(decode_video(mp4.string()).frames, 15);
    bytes[i] = fs::file_size(mp4);
  }
  EXPECT_LT(bytes[1], bytes[0]) << "veryslow packs the same frames tighter";
}

TEST_F(CliRenderTest, EglAndOsmesaDrawTheSameFrames) {
  const fs::path dir = fresh_dir("render_backends");
  const std::string common =
      "render scenarios/drop_mass.toml --set sim.duration_s=0.2 --set drop.time_s=0.1 "
      "--width 320 --height 180 --fps 10 --quality fast --plot --png-dir ";
  const CliResult osmesa = run_pamsim(common + (dir / "osmesa").string() + " --backend osmesa");
  ASSERT_EQ(osmesa.exit_code, 0) << osmesa.err;
  ::setenv("PAMSIM_GL_BACKEND", "egl", 1);  // the environment picks the backend too
  const CliResult egl = run_pamsim(common + (dir / "egl").string());
  ASSERT_EQ(egl.exit_code, 0) << egl.err;
  EXPECT_NE(egl.err.find("egl"), std::string::npos) << egl.err;

  expect_exactly(dir / "osmesa", {"frame_00000.png", "frame_00001.png"});
  for (const char* frame : {"frame_00000.png", "frame_00001.png"}) {
    const auto a = decode_video((dir / "osmesa" / frame).string(), 1);
    const auto b = decode_video((dir / "egl" / frame).string(), 1);
    ASSERT_TRUE(a.opened && b.opened) << frame;
    EXPECT_EQ(a.width, 320);
    EXPECT_EQ(a.height, 180);
    EXPECT_TRUE(a.rgb.at(0) == b.rgb.at(0)) << frame << ": both are Mesa's llvmpipe";
  }
}

// The GL line of a render's stderr ("pamsim: GL: ...").
std::string gl_line(const std::string& err) {
  const std::size_t at = err.find("pamsim: GL: ");
  return at == std::string::npos ? "" : err.substr(at, err.find('\n', at) - at);
}

// EGL device selection on Mesa's software EGL device (EGL_MESA_device_software), which every
// Mesa machine lists, GPU or not: chosen by --gpu, by EGL_DEVICE_ID and by MUJOCO_GL; its
// frames are the same from run to run; the renderer is named; an unknown device is refused.
TEST_F(CliRenderTest, EglDeviceIsChosenNamedAndDrawsTheSameFramesEveryRun) {
  const fs::path dir = fresh_dir("render_egl_device");
  const std::string common =
      "render scenarios/drop_mass.toml --set sim.duration_s=0.2 --set drop.time_s=0.1 "
      "--width 320 --height 180 --fps 10 --plot --png-dir ";
  const CliResult a = run_pamsim(common + (dir / "a").string() + " --backend egl --gpu 0");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(gl_line(a.err).rfind("pamsim: GL: egl device 0 of ", 0), 0u) << a.err;
  EXPECT_NE(gl_line(a.err).find("OpenGL "), std::string::npos) << a.err;
  const CliResult b =
      run_pamsim(common + (dir / "b").string(), "env MUJOCO_GL=egl EGL_DEVICE_ID=0");
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(gl_line(b.err), gl_line(a.err)) << "the environment chooses the same device";
  for (const char* frame : {"frame_00000.png", "frame_00001.png"}) {
    EXPECT_EQ(read_file(dir / "a" / frame), read_file(dir / "b" / frame)) << frame;
  }
  // no device asked for, no GPU: Mesa's surfaceless platform, or the first GPU where one is
  const CliResult any = run_pamsim(common + (dir / "any").string() + " --backend egl");
  ASSERT_EQ(any.exit_code, 0) << any.err;
  EXPECT_EQ(gl_line(any.err).rfind("pamsim: GL: egl ", 0), 0u) << any.err;
  if (gl_line(any.err).rfind("pamsim: GL: egl surfaceless", 0) == 0) {  // says why no device
    EXPECT_NE(gl_line(any.err).find("egl surfaceless (no GPU device: EGL lists "),
              std::string::npos)
        << any.err;
  }
}

// Where EGL gives no context (here: GLVND finds no vendor library), egl falls back to
// osmesa and says why; a device asked for by number has no substitute.
TEST_F(CliRenderTest, EglWithoutADriverFallsBackToOsmesaAndSaysWhy) {
  const fs::path dir = fresh_dir("render_egl_fallback");
  const std::string common =
      "render scenarios/drop_mass.toml --set sim.duration_s=0.2 --set drop.time_s=0.1 "
      "--width 320 --height 180 --fps 10 --backend egl --png-dir ";
  const std::string no_driver = "env __EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json";
  const CliResult r = run_pamsim(common + (dir / "fallback").string(), no_driver);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(gl_line(r.err).rfind("pamsim: GL: osmesa (egl unavailable: ", 0), 0u) << r.err;
  expect_exactly(dir / "fallback", {"frame_00000.png", "frame_00001.png"});
  const CliResult named = run_pamsim(common + (dir / "named").string() + " --gpu 0", no_driver);
  EXPECT_EQ(named.exit_code, 2) << named.err;
  EXPECT_EQ(line_count(named.err), 1) << named.err;
  EXPECT_NE(named.err.find("--gpu 0: no such EGL device; the devices here: none"),
            std::string::npos)
      << named.err;
  EXPECT_FALSE(fs::exists(dir / "named"));
}

TEST_F(CliRenderTest, BadInputIsOneLineNonZeroAndLeavesNothing) {
  const fs::path dir = fresh_dir("render_bad");
  const fs::path blocker = dir / "a_file";
  pamsim_test::write_text(blocker, "not a folder");
  const std::string mp4 = (dir / "v.mp4").string();
  const std::string render =
      "render scenarios/drop_mass.toml --set sim.duration_s=0.1 --set drop.time_s=0.05 ";
  // the arm without its "side" camera, kept outside `dir`
  const fs::path no_side = fresh_dir("render_bad_model") / "arm_no_side.xml";
  std::string xml = pamsim_test::read_file(std::string(PAMSIM_SOURCE_DIR) + "/models/arm_2pam.xml");
  xml.replace(xml.find("name=\"side\""), 11, "name=\"back\"");
  pamsim_test::write_text(no_side, xml);
  const std::vector<std::string> cases = {
      render + "-o /proc/pamsim_no_such/v.mp4",       // unwritable
      render + "-o " + (blocker / "v.mp4").string(),  // parent is a file
      render + "-o " + (dir / "v.avi").string(),      // not .mp4
      render + "-o " + mp4 + " --width 0",
      render + "-o " + mp4 + " --height 0",
      render + "-o " + mp4 + " --width 100000",
      render + "-o " + mp4 + " --height 100000",
      render + "-o " + mp4 + " --width 641",  // odd: 4:2:0 needs even
      render + "-o " + mp4 + " --fps 0",
      render + "-o " + mp4 + " --fps -5",
      render + "-o " + mp4 + " --fps 1000",
      render + "-o " + mp4 + " --fps abc",
      render + "-o " + mp4 + " --quality best",
      render + "-o " + mp4 + " --preset turbo",
      render + "-o " + mp4 + " --camera top",
      render + "-o " + mp4 + " --backend vulkan",
      render + "-o " + mp4 + " --backend egl --gpu 99",  // no such EGL device
      render + "-o " + mp4 + " --backend egl --gpu -3",
      render + "-o " + mp4 + " --gpu 0",  // a device, but osmesa
      "render scenarios/missing.toml -o " + mp4,
      render + "--png-dir " + dir.string(),  // holds other files
      "run scenarios/drop_mass.toml --trials 2 --video " + mp4 + " --out " + (dir / "o").string(),
      "run scenarios/drop_mass.toml --video " + (dir / "v.mov").string() + " --out " +
          (dir / "o").string(),
      "run scenarios/drop_mass.toml --set model.file=\\\"" + no_side.string() + "\\\" --video " +
          mp4 + " --out " + (dir / "o").string(),  // no camera: no output folder
  };
  for (const std::string& args : cases) {
    const CliResult r = run_pamsim(args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("pamsim: ", 0), 0u) << args << ": " << r.err;
    expect_exactly(dir, {"a_file"});
  }

  // the unknown camera's message lists the model's cameras; the environment is checked too
  const CliResult camera = run_pamsim(render + "-o " + mp4 + " --camera top");
  EXPECT_NE(camera.err.find("(the model's cameras: side, wide)"), std::string::npos) << camera.err;
  ::setenv("PAMSIM_GL_BACKEND", "vulkan", 1);
  const CliResult env = run_pamsim(render + "-o " + mp4);
  EXPECT_EQ(env.exit_code, 2);
  EXPECT_EQ(env.err, "pamsim: PAMSIM_GL_BACKEND must be osmesa or egl, got 'vulkan'\n");
  expect_exactly(dir, {"a_file"});
}

}  // namespace
