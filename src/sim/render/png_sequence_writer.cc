// png_sequence_writer.cc: see png_sequence_writer.h.
#include "sim/render/png_sequence_writer.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>
#include <system_error>

#include "base/atomic_file.h"
#include "base/input_error.h"
#include "sim/render/av_handles.h"
#include "sim/io/temp_path.h"

extern "C" {
#include <libavutil/imgutils.h>
}

namespace pamsim {
namespace {

namespace fs = std::filesystem;

// zlib level 1-9: 3 is several times faster than the default at a few percent more bytes
constexpr int kPngCompressionLevel = 3;

// Throws unless `dir` is absent or a folder of nothing but an earlier frame sequence.
void check_replaceable(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) return;
  if (!fs::is_directory(dir, ec)) throw InputError(dir + ": exists and is not a folder");
  static const std::regex frame_name(R"(frame_\d+\.png)");
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (!std::regex_match(entry.path().filename().string(), frame_name)) {
      throw InputError(dir + ": holds files other than frame_*.png (" +
                       entry.path().filename().string() + "); choose a new or empty folder");
    }
  }
  if (ec) throw InputError(dir + ": cannot read folder (" + ec.message() + ")");
}

std::string frame_file_name(long index) {
  char name[32];
  std::snprintf(name, sizeof(name), "/frame_%05ld.png", index);
  return name;
}

// libavcodec's PNG encoder on RGB frames of width x height; `where` names the output
AvCodecContextPtr open_png_encoder(int width_px, int height_px, const std::string& where) {
  quiet_ffmpeg_log();
  const AVCodec* codec = avcodec_find_encoder(AV_CODEC_ID_PNG);
  if (!codec) throw InputError(where + ": this FFmpeg has no PNG encoder");
  AvCodecContextPtr encoder(avcodec_alloc_context3(codec));
  if (!encoder) throw std::bad_alloc();
  encoder->width = width_px;
  encoder->height = height_px;
  encoder->pix_fmt = AV_PIX_FMT_RGB24;
  encoder->time_base = AVRational{1, 1};
  encoder->compression_level = kPngCompressionLevel;
  check_av(avcodec_open2(encoder.get(), codec, nullptr), where, "cannot open the PNG encoder");
  return encoder;
}

// One frame (rows bottom-up) encoded as a whole PNG file into `packet`.
void encode_png(AVCodecContext* encoder, AVFrame* frame, AVPacket* packet,
                const unsigned char* rgb_bottom_up, long pts, const std::string& where) {
  check_av(av_frame_make_writable(frame), where, "frame buffer");
  // copy the rows last to first: PNG stores them top-down
  const int row_bytes = 3 * frame->width;
  av_image_copy_plane(frame->data[0], frame->linesize[0],
                      rgb_bottom_up + static_cast<std::ptrdiff_t>(frame->height - 1) * row_bytes,
                      -row_bytes, row_bytes, frame->height);
  frame->pts = pts;
  check_av(avcodec_send_frame(encoder, frame), where, "PNG encoding failed");
  check_av(avcodec_receive_packet(encoder, packet), where, "PNG encoding failed");
}

}  // namespace

void write_png_file(const std::string& path, const unsigned char* rgb_bottom_up, int width_px,
                    int height_px) {
  if (width_px <= 0 || height_px <= 0) throw InputError(path + ": image size must be > 0");
  AvCodecContextPtr encoder = open_png_encoder(width_px, height_px, path);
  AvFramePtr frame = alloc_frame(width_px, height_px, AV_PIX_FMT_RGB24);
  AvPacketPtr packet(av_packet_alloc());
  if (!packet) throw std::bad_alloc();
  encode_png(encoder.get(), frame.get(), packet.get(), rgb_bottom_up, 0, path);
  write_file_atomically(path, std::string(reinterpret_cast<const char*>(packet->data),
                                          static_cast<std::size_t>(packet->size)));
}

// Members are destroyed bottom-up: the encoder goes first, then the temp folder.
struct PngSequenceWriter::Impl {
  explicit Impl(const std::string& dir) : temp_dir(dir, TempKind::kFolder) {}
  TempPath temp_dir;
  AvCodecContextPtr encoder;
  AvFramePtr frame;    // RGB rows top-down, reused
  AvPacketPtr packet;  // reused
};

PngSequenceWriter::PngSequenceWriter(const std::string& dir, int width_px, int height_px)
    : dir_(fs::path(dir).lexically_normal().string()) {
  // a trailing slash would put the temp folder inside DIR
  if (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
  if (width_px <= 0 || height_px <= 0) throw InputError(dir_ + ": frame size must be > 0");
  check_replaceable(dir_);
  // the temp folder, beside DIR
  std::error_code ec;
  const fs::path parent = fs::path(dir_).parent_path();
  if (!parent.empty()) fs::create_directories(parent, ec);
  if (ec) throw InputError(dir_ + ": cannot create folder (" + ec.message() + ")");
  impl_ = std::make_unique<Impl>(dir_);
  Impl& x = *impl_;

  x.encoder = open_png_encoder(width_px, height_px, dir_);
  x.frame = alloc_frame(width_px, height_px, AV_PIX_FMT_RGB24);
  x.packet.reset(av_packet_alloc());
  if (!x.packet) throw std::bad_alloc();
}

PngSequenceWriter::~PngSequenceWriter() = default;

void PngSequenceWriter::write_frame(const unsigned char* rgb_bottom_up) {
  Impl& x = *impl_;
  encode_png(x.encoder.get(), x.frame.get(), x.packet.get(), rgb_bottom_up, frames_written_, dir_);
  // one packet per frame: the whole PNG file
  AVPacket* packet = x.packet.get();
  const std::string file = x.temp_dir.path() + frame_file_name(frames_written_);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(packet->data), packet->size);
  av_packet_unref(packet);
  if (!out.flush()) throw std::runtime_error(dir_ + ": cannot write " + file);
  ++frames_written_;
}

void PngSequenceWriter::finish() {
  // replace an earlier sequence (checked again: it may have changed since the start)
  // the old one is moved aside first, so a failed rename loses neither sequence
  check_replaceable(dir_);
  std::error_code ec;
  const std::string old_dir = impl_->temp_dir.path() + ".old";
  const bool had_old = fs::exists(dir_, ec);
  if (had_old) fs::rename(dir_, old_dir, ec);
  if (!ec) fs::rename(impl_->temp_dir.path(), dir_, ec);
  if (ec) {
    std::error_code ignored;
    if (had_old && !fs::exists(dir_, ignored)) fs::rename(old_dir, dir_, ignored);
    throw InputError(dir_ + ": cannot put the frames in place (" + ec.message() + ")");
  }
  if (had_old) fs::remove_all(old_dir, ec);
  impl_->temp_dir.release();
  impl_.reset();
}

}  // namespace pamsim
