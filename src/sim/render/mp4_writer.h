// mp4_writer.h: an H.264 video in an MP4 file, written through FFmpeg's libraries in this
// process as frames arrive: each RGB frame is converted to YUV 4:2:0 by libswscale (which
// also flips OpenGL's bottom-up rows), encoded by libx264 (or another H.264 encoder of this
// FFmpeg) and muxed by libavformat, on a thread of its own, while the caller draws the next
// frame. Nothing is kept but one frame in hand-over and the encoder's own lookahead.
// The file is written as `<path>.tmp.<pid>` and renamed into place by finish(); a writer
// destroyed before finish() removes its temp file, so a failed run leaves no partial video.
// Path "-" streams a fragmented MP4 to standard output instead (for a pipe into ffplay or
// ffmpeg; what was written is not taken back on failure).
#pragma once

#include <memory>
#include <string>

namespace pamsim {

struct Mp4Settings {
  int width_px = 1280;  // even, as 4:2:0 chroma needs
  int height_px = 720;  // even
  int fps = 30;
  std::string x264_preset = "veryfast";  // libx264's speed/size trade-off
  int x264_crf = 23;                     // constant quality, lower is better (0-51)
};

class Mp4Writer {
 public:
  // Opens the temp file and the encoder. Throws InputError naming `path` if the folder is
  // not writable or the size is odd or not positive, or if FFmpeg has no H.264 encoder.
  Mp4Writer(const std::string& path, const Mp4Settings& settings);
  ~Mp4Writer();
  Mp4Writer(const Mp4Writer&) = delete;
  Mp4Writer& operator=(const Mp4Writer&) = delete;

  // Hands one frame to the encoding thread (copied: the caller may reuse its buffer) and
  // returns; waits only while the previous frame is still being taken. Frame: width * height
  // RGB triplets, rows bottom-up (as mjr_readPixels gives them); frames are 1/fps apart.
  // Throws std::runtime_error if encoding or writing an earlier frame failed.
  void write_frame(const unsigned char* rgb_bottom_up);

  // Encodes the frames still in hand, drains the encoder, completes the file and renames it
  // into place. Call once, last. Throws as write_frame, or InputError if the rename fails.
  void finish();

  long frames_written() const { return frames_written_; }
  // "libx264" or whichever H.264 encoder was found
  const std::string& encoder_name() const { return encoder_name_; }

 private:
  struct Impl;

  std::string path_;
  long frames_written_ = 0;
  std::string encoder_name_;
  std::unique_ptr<Impl> impl_;  // FFmpeg's objects (av_handles.h)
};

}  // namespace pamsim
