// scene_renderer_test.cc: SceneRenderer on a tiny inline model, offscreen through OSMesa: the
// frame is not empty, a falling ball moves down in it, drawing never writes to the caller's
// mjData, and an unknown camera or a bad size is refused with a clear message.
#include "sim/render/scene_renderer.h"
#include "sim/render/trial_video.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "sim/inline_mjcf.h"
#include "base/input_error.h"

namespace pamsim {
namespace {

using pamsim_test::load_inline;

// A red ball falling in front of a camera that looks along +y; nothing else to see.
constexpr char kFallingBallXml[] = R"(
<mujoco>
  <option timestep="0.002"/>
  <worldbody>
    <light pos="0 -1 2" dir="0 0.5 -1"/>
    <camera name="front" pos="0 -2 0" xyaxes="1 0 0 0 0 1" fovy="60"/>
    <camera name="top" pos="0 0 3" xyaxes="1 0 0 0 1 0"/>
    <body name="ball" pos="0 0 0.6">
      <freejoint/>
      <geom type="sphere" size="0.25" rgba="1 0 0 1"/>
    </body>
  </worldbody>
</mujoco>)";

constexpr int kSceneWidth = 160;
constexpr int kSceneHeight = 120;

struct RedBlob {
  int pixels = 0;
  double mean_row = 0;  // counted from the bottom, as OpenGL reads them
};

RedBlob find_red(const unsigned char* rgb) {
  RedBlob blob;
  for (int row = 0; row < kSceneHeight; ++row) {
    for (int x = 0; x < kSceneWidth; ++x) {
      const unsigned char* px = rgb + 3 * (row * kSceneWidth + x);
      if (px[0] > 100 && px[1] < 60 && px[2] < 60) {
        ++blob.pixels;
        blob.mean_row += row;
      }
    }
  }
  if (blob.pixels > 0) blob.mean_row /= blob.pixels;
  return blob;
}

int distinct_colours(const unsigned char* rgb) {
  std::vector<bool> seen(1 << 24);
  int n = 0;
  for (int i = 0; i < kSceneWidth * kSceneHeight; ++i) {
    const int c = (rgb[3 * i] << 16) | (rgb[3 * i + 1] << 8) | rgb[3 * i + 2];
    if (!seen[c]) {
      seen[c] = true;
      ++n;
    }
  }
  return n;
}

SceneRenderOptions small_frame(const std::string& camera = "front") {
  SceneRenderOptions options;
  options.width_px = kSceneWidth;
  options.height_px = kSceneHeight;
  options.camera = camera;
  return options;
}

TEST(SceneRendererTest, FrameIsNotEmptyAndTheFallingBallMovesDown) {
  MjModelPtr model = load_inline(kFallingBallXml, "ball.xml");
  ASSERT_TRUE(model);
  MjDataPtr data = make_data(model.get());
  mj_forward(model.get(), data.get());
  SceneRenderer renderer(model.get(), "ball.xml", small_frame());

  renderer.draw_scene(data.get());
  std::vector<unsigned char> before(renderer.read_pixels(),
                                    renderer.read_pixels() + 3 * kSceneWidth * kSceneHeight);
  const RedBlob start = find_red(before.data());
  EXPECT_GT(distinct_colours(before.data()), 10) << "not one flat colour";
  ASSERT_GT(start.pixels, 200) << "the ball is in view";
  EXPECT_GT(start.mean_row, kSceneHeight / 2) << "upper half at the start";

  // 0.4 s of free fall: 0.78 m down, from z = 0.6 to -0.18 (the view spans z = +-1.15 m)
  for (int i = 0; i < 200; ++i) mj_step(model.get(), data.get());
  renderer.draw_scene(data.get());
  const RedBlob later = find_red(renderer.read_pixels());
  ASSERT_GT(later.pixels, 200);
  EXPECT_LT(later.mean_row, start.mean_row - 20) << "the ball moved down the frame";
}

// The backdrop is plain and light (not MuJoCo's black), and a capsule given to draw_scene
// (a muscle) appears in its colour where it was put.
TEST(SceneRendererTest, APlainLightBackdropAndAddedCapsulesInTheirColour) {
  MjModelPtr model = load_inline(kFallingBallXml, "ball.xml");
  ASSERT_TRUE(model);
  MjDataPtr data = make_data(model.get());
  mj_forward(model.get(), data.get());
  SceneRenderer renderer(model.get(), "ball.xml", small_frame());
  renderer.draw_scene(data.get());
  const unsigned char* corner = renderer.read_pixels() + 3 * ((kSceneHeight - 2) * kSceneWidth + 2);
  for (int c = 0; c < 3; ++c) EXPECT_GT(corner[c], 200) << "channel " << c;

  // a green capsule across the lower part of the frame (the ball is above it)
  SceneRenderer::Capsule muscle{{-0.6, 0, -0.5}, {0.6, 0, -0.5}, 0.08, {0.1f, 0.9f, 0.1f, 1.0f}};
  renderer.draw_scene(data.get(), {muscle});
  const unsigned char* rgb = renderer.read_pixels();
  int green = 0;
  double mean_row = 0;
  for (int row = 0; row < kSceneHeight; ++row) {
    for (int x = 0; x < kSceneWidth; ++x) {
      const unsigned char* px = rgb + 3 * (row * kSceneWidth + x);
      if (px[1] > 120 && px[0] < 90 && px[2] < 90) {
        ++green;
        mean_row += row;
      }
    }
  }
  ASSERT_GT(green, 100);
  EXPECT_LT(mean_row / green, kSceneHeight / 2) << "drawn where it was put: the lower half";
}

TEST(SceneRendererTest, DrawingNeverWritesTheCallersData) {
  MjModelPtr model = load_inline(kFallingBallXml, "ball.xml");
  ASSERT_TRUE(model);
  MjDataPtr data = make_data(model.get());
  for (int i = 0; i < 10; ++i) mj_step(model.get(), data.get());
  const std::vector<unsigned char> buffer_before(
      static_cast<unsigned char*>(data->buffer),
      static_cast<unsigned char*>(data->buffer) + model->nbuffer);

  SceneRenderer renderer(model.get(), "ball.xml", small_frame());
  renderer.draw_scene(data.get());
  renderer.draw_text("time", "0.020 s");
  renderer.read_pixels();
  EXPECT_EQ(std::memcmp(buffer_before.data(), data->buffer, model->nbuffer), 0);
}

TEST(SceneRendererTest, UnknownCameraNamesTheModelsCameras) {
  MjModelPtr model = load_inline(kFallingBallXml, "ball.xml");
  ASSERT_TRUE(model);
  try {
    SceneRenderer renderer(model.get(), "ball.xml", small_frame("back"));
    FAIL() << "no camera 'back' in the model";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "ball.xml: no camera named 'back' (the model's cameras: front, top)");
  }
}

TEST(SceneRendererTest, SizeOutsideTheLimitsIsRefused) {
  MjModelPtr model = load_inline(kFallingBallXml, "ball.xml");
  ASSERT_TRUE(model);
  for (const auto& [w, h] :
       {std::pair{0, 120}, {160, 8}, {100000, 120}, {160, kMaxFrameSidePx + 1}}) {
    SceneRenderOptions options = small_frame();
    options.width_px = w;
    options.height_px = h;
    EXPECT_THROW(SceneRenderer(model.get(), "ball.xml", options), InputError) << w << "x" << h;
  }
}

}  // namespace
}  // namespace pamsim

namespace pamsim {
namespace {

// A live plot's four time labels are told apart with the fewest decimals: no "0 0.1 0.1 0.2".
TEST(FigureTimeFormatTest, LabelsAreDistinctWithTheFewestDecimals) {
  EXPECT_EQ(figure_time_format(3.0, 4), "%.0f");   // 0 1 2 3
  EXPECT_EQ(figure_time_format(1.2, 4), "%.1f");   // 0 0.4 0.8 1.2
  EXPECT_EQ(figure_time_format(0.15, 4), "%.2f");  // 0 0.05 0.10 0.15
  EXPECT_EQ(figure_time_format(0.1, 4), "%.3f");   // 0.033..., as close as three digits go
  for (const double duration : {0.15, 0.3, 0.6, 1.5, 4.5}) {
    const std::string format = figure_time_format(duration, 4);
    std::vector<std::string> labels;
    for (int k = 0; k < 4; ++k) {
      char label[32];
      std::snprintf(label, sizeof(label), format.c_str(), duration * k / 3);
      labels.push_back(label);
    }
    for (int k = 1; k < 4; ++k) EXPECT_NE(labels[k], labels[k - 1]) << duration << " " << format;
  }
}

}  // namespace
}  // namespace pamsim
