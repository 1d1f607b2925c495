// png_sequence_writer.h: a video as numbered PNG images, DIR/frame_00000.png, ..., encoded by
// libavcodec's PNG encoder as frames arrive (for frame-by-frame comparison of trials).
// Frames are written into a temp folder beside DIR that replaces DIR in finish(); a writer
// destroyed before finish() removes it, so a failed run leaves no partial sequence. An
// existing DIR is replaced only if it holds nothing but frame_*.png files (an earlier
// sequence); a folder with anything else in it is refused, never emptied. And one image as a
// PNG file.
#pragma once

#include <memory>
#include <string>

namespace pamsim {

// One image (width * height RGB triplets, rows bottom-up, as mjr_readPixels gives them) as
// the PNG file `path`, written atomically (a screenshot). Throws InputError naming the path.
void write_png_file(const std::string& path, const unsigned char* rgb_bottom_up, int width_px,
                    int height_px);

class PngSequenceWriter {
 public:
  // Throws InputError naming `dir` if it exists with other files in it, is not a folder, or
  // cannot be created, or if the size is not positive.
  PngSequenceWriter(const std::string& dir, int width_px, int height_px);
  ~PngSequenceWriter();
  PngSequenceWriter(const PngSequenceWriter&) = delete;
  PngSequenceWriter& operator=(const PngSequenceWriter&) = delete;

  // Writes the next frame: width * height RGB triplets, rows bottom-up (mjr_readPixels).
  // Throws std::runtime_error if encoding or writing fails.
  void write_frame(const unsigned char* rgb_bottom_up);

  // Puts the sequence in place as DIR. Call once, last.
  void finish();

 private:
  struct Impl;

  std::string dir_;
  long frames_written_ = 0;
  std::unique_ptr<Impl> impl_;  // FFmpeg's objects and the temp folder
};

}  // namespace pamsim
