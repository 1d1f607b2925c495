// png_sequence_writer_test.cc: PngSequenceWriter: numbered PNGs that FFmpeg decodes at the
// right size and the right way up, an earlier sequence replaced as a whole, a folder with
// other files refused untouched, and an unfinished sequence leaving nothing behind.
#include "sim/render/png_sequence_writer.h"

#include <gtest/gtest.h>
#include <unistd.h>

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
using pamsim_test::write_text;

constexpr int kPngWidth = 30;  // odd sizes are fine for PNG
constexpr int kPngHeight = 17;

// Bottom-up RGB: the bottom row green, everything else grey.
std::vector<unsigned char> test_frame() {
  std::vector<unsigned char> rgb(3 * kPngWidth * kPngHeight, 90);
  for (int x = 0; x < kPngWidth; ++x) {
    rgb[3 * x] = 0;
    rgb[3 * x + 1] = 255;
    rgb[3 * x + 2] = 0;
  }
  return rgb;
}

void write_sequence(const fs::path& dir, int frames) {
  PngSequenceWriter writer(dir.string(), kPngWidth, kPngHeight);
  for (int f = 0; f < frames; ++f) writer.write_frame(test_frame().data());
  writer.finish();
}

int file_count(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(PngSequenceWriterTest, NumberedFramesDecodeTopDown) {
  const fs::path dir = fresh_dir("png_seq_ok") / "frames";
  write_sequence(dir, 3);
  EXPECT_EQ(file_count(dir), 3);
  const auto png = decode_video((dir / "frame_00002.png").string(), 1);
  ASSERT_TRUE(png.opened);
  EXPECT_EQ(png.codec, "png");
  EXPECT_EQ(png.width, kPngWidth);
  EXPECT_EQ(png.height, kPngHeight);
  const auto& rgb = png.rgb.at(0);
  const unsigned char* last_row = &rgb[3 * (kPngHeight - 1) * kPngWidth];
  EXPECT_EQ(last_row[1], 255) << "OpenGL's bottom row is the image's last";
  EXPECT_EQ(rgb[1], 90);
  EXPECT_EQ(file_count(dir.parent_path()), 1) << "no temp folder left";
}

TEST(PngSequenceWriterTest, AnEarlierSequenceIsReplacedWhole) {
  const fs::path dir = fresh_dir("png_seq_again") / "frames";
  write_sequence(dir, 5);
  write_sequence(dir, 2);
  EXPECT_EQ(file_count(dir), 2);
}

TEST(PngSequenceWriterTest, AFolderWithOtherFilesIsRefusedUntouched) {
  const fs::path dir = fresh_dir("png_seq_refuse");
  write_text(dir / "notes.txt", "mine");
  EXPECT_THROW(PngSequenceWriter(dir.string(), kPngWidth, kPngHeight), InputError);
  EXPECT_EQ(file_count(dir), 1);
  EXPECT_FALSE(fs::exists(dir.string() + ".tmp." + std::to_string(::getpid())));
}

TEST(PngSequenceWriterTest, UnfinishedSequenceLeavesNothing) {
  const fs::path parent = fresh_dir("png_seq_abandon");
  {
    PngSequenceWriter writer((parent / "frames").string(), kPngWidth, kPngHeight);
    writer.write_frame(test_frame().data());
  }
  EXPECT_TRUE(fs::is_empty(parent));
}

}  // namespace
}  // namespace pamsim
