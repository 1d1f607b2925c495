// mp4_writer_test.cc: Mp4Writer against FFmpeg's own decoder: every frame written is decoded
// back at the right size, OpenGL's bottom-up rows come out top-down, and a writer that does
// not finish (or cannot start) leaves no file and no temp file behind.
#include "sim/render/mp4_writer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <vector>

#include "sim/cli_util.h"
#include "base/input_error.h"
#include "sim/video_decode.h"

namespace pamsim {
namespace {

namespace fs = std::filesystem;
using pamsim_test::decode_video;
using pamsim_test::fresh_dir;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// Bottom-up RGB: the bottom half red, the top half blue, and a white column at x = frame.
std::vector<unsigned char> test_frame(int frame) {
  std::vector<unsigned char> rgb(3 * kWidth * kHeight);
  for (int row = 0; row < kHeight; ++row) {  // row 0 is the bottom
    for (int x = 0; x < kWidth; ++x) {
      unsigned char* px = &rgb[3 * (row * kWidth + x)];
      const bool bottom = row < kHeight / 2;
      px[0] = bottom ? 220 : 20;
      px[1] = 20;
      px[2] = bottom ? 20 : 220;
      if (x == frame % kWidth) px[0] = px[1] = px[2] = 255;
    }
  }
  return rgb;
}

Mp4Settings small_video() {
  Mp4Settings settings;
  settings.width_px = kWidth;
  settings.height_px = kHeight;
  return settings;
}

bool has_temp_file(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().filename().string().find(".tmp") != std::string::npos) return true;
  }
  return false;
}

TEST(Mp4WriterTest, EveryFrameDecodesAtItsSizeTopDown) {
  const fs::path dir = fresh_dir("mp4_writer_ok");
  const std::string path = (dir / "v.mp4").string();
  Mp4Settings settings = small_video();
  settings.fps = 25;
  {
    Mp4Writer writer(path, settings);
    EXPECT_FALSE(fs::exists(path)) << "nothing at the path before finish()";
    for (int f = 0; f < 12; ++f) writer.write_frame(test_frame(f).data());
    writer.finish();
    EXPECT_EQ(writer.frames_written(), 12);
    EXPECT_EQ(writer.encoder_name(), "libx264");
  }
  const auto video = decode_video(path, 1);
  ASSERT_TRUE(video.opened);
  EXPECT_EQ(video.codec, "h264");
  EXPECT_EQ(video.width, kWidth);
  EXPECT_EQ(video.height, kHeight);
  EXPECT_EQ(video.frames, 12);
  // the decoded first row (top of the picture) is blue, the last row (bottom) red
  const auto& rgb = video.rgb.at(0);
  const unsigned char* top = &rgb[3 * (2 * kWidth + kWidth / 2)];
  const unsigned char* bottom = &rgb[3 * ((kHeight - 3) * kWidth + kWidth / 2)];
  EXPECT_GT(top[2], 150);
  EXPECT_LT(top[0], 80);
  EXPECT_GT(bottom[0], 150);
  EXPECT_LT(bottom[2], 80);
  EXPECT_FALSE(has_temp_file(dir));
}

TEST(Mp4WriterTest, UnfinishedWriterLeavesNothing) {
  const fs::path dir = fresh_dir("mp4_writer_abandon");
  const std::string path = (dir / "v.mp4").string();
  {
    Mp4Writer writer(path, small_video());
    writer.write_frame(test_frame(0).data());
    EXPECT_TRUE(has_temp_file(dir)) << "frames stream into a temp file";
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(has_temp_file(dir));
}

TEST(Mp4WriterTest, BadSizeOrFolderIsAnInputErrorAndLeavesNothing) {
  const fs::path dir = fresh_dir("mp4_writer_bad");
  Mp4Settings odd = small_video();
  odd.width_px = kWidth + 1;
  EXPECT_THROW(Mp4Writer((dir / "odd.mp4").string(), odd), InputError);
  Mp4Settings zero = small_video();
  zero.height_px = 0;
  EXPECT_THROW(Mp4Writer((dir / "zero.mp4").string(), zero), InputError);
  EXPECT_THROW(Mp4Writer((dir / "missing" / "v.mp4").string(), small_video()), InputError);
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
}  // namespace pamsim
