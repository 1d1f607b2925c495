// mp4_writer.cc: see mp4_writer.h.
#include "sim/render/mp4_writer.h"

#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "base/input_error.h"
#include "sim/render/av_handles.h"
#include "sim/io/temp_path.h"

extern "C" {
#include <libavutil/dict.h>
}

namespace pamsim {
namespace {

// libx264 when this FFmpeg has it, else any other H.264 encoder
const AVCodec* find_h264_encoder() {
  const AVCodec* codec = avcodec_find_encoder_by_name("libx264");
  return codec ? codec : avcodec_find_encoder(AV_CODEC_ID_H264);
}

// The H.264 encoder for `settings`, checked first: an even width and height (4:2:0), a
// positive fps. Throws InputError naming `path`.
const AVCodec* checked_h264_encoder(const std::string& path, const Mp4Settings& settings) {
  const int w = settings.width_px;
  const int h = settings.height_px;
  if (w <= 0 || h <= 0 || w % 2 != 0 || h % 2 != 0) {
    throw InputError(path + ": H.264 (4:2:0) needs an even width and height, got " +
                     std::to_string(w) + "x" + std::to_string(h));
  }
  if (settings.fps <= 0) throw InputError(path + ": fps must be > 0");
  const AVCodec* codec = find_h264_encoder();
  if (!codec) {
    throw InputError(path +
                     ": this FFmpeg has no H.264 encoder (install libavcodec with "
                     "libx264, or write a PNG sequence instead)");
  }
  return codec;
}

}  // namespace

// The FFmpeg objects, and the thread that converts, encodes and writes each frame while the
// caller draws the next one. Members are destroyed bottom-up, after the thread has stopped:
// the muxer closes the file before the guard removes it (also when the constructor throws
// half way).
struct Mp4Writer::Impl {
  explicit Impl(const std::string& output)
      : path(output),
        temp_file(output == "-" ? nullptr : std::make_unique<TempPath>(output, TempKind::kFile)) {}
  ~Impl() { stop_encoding_thread(); }

  // the constructor's steps, in order
  void make_encoder(const AVCodec* codec, const Mp4Settings& settings);
  void open_muxer(const std::string& target);
  void open_encoder_and_write_header(const AVCodec* codec, const Mp4Settings& settings,
                                     bool streamed);
  void make_converter(int w, int h);

  void encoding_loop();
  void encode(const unsigned char* rgb_bottom_up);
  void drain_packets();
  void stop_encoding_thread();

  std::string path;
  std::unique_ptr<TempPath> temp_file;  // none for "-": standard output, streamed
  AvOutputContextPtr muxer;
  AVStream* stream = nullptr;  // owned by the muxer
  AvCodecContextPtr encoder;
  SwsContextPtr rgb_to_yuv;
  AvFramePtr frame;    // the YUV frame handed to the encoder, reused
  AvPacketPtr packet;  // reused
  long frames_encoded = 0;

  // hand-over of one frame at a time from the caller to the encoding thread
  std::thread encoding_thread;
  std::mutex mutex;
  std::condition_variable changed;
  std::vector<unsigned char> handed_over;  // RGB, bottom-up
  bool frame_waiting = false;
  bool closing = false;
  std::exception_ptr failure;  // from the encoding thread, rethrown to the caller
};

void Mp4Writer::Impl::encoding_loop() {
  std::vector<unsigned char> rgb(handed_over.size());
  for (;;) {
    // take the next frame (swap buffers) or stop once closing with none left
    {
      std::unique_lock<std::mutex> lock(mutex);
      changed.wait(lock, [&] { return frame_waiting || closing; });
      if (!frame_waiting) return;
      rgb.swap(handed_over);
      frame_waiting = false;
    }
    changed.notify_all();
    try {
      encode(rgb.data());
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      failure = std::current_exception();
      changed.notify_all();
      return;
    }
  }
}

void Mp4Writer::Impl::encode(const unsigned char* rgb_bottom_up) {
  // the encoder may still hold the previous frame's buffer
  AVFrame* f = frame.get();
  check_av(av_frame_make_writable(f), path, "frame buffer");

  // start at the last row and step backwards: the flip costs nothing extra
  const int row_bytes = 3 * f->width;
  const uint8_t* src[1] = {rgb_bottom_up + static_cast<std::ptrdiff_t>(f->height - 1) * row_bytes};
  const int src_stride[1] = {-row_bytes};
  sws_scale(rgb_to_yuv.get(), src, src_stride, 0, f->height, f->data, f->linesize);

  f->pts = frames_encoded++;
  check_av(avcodec_send_frame(encoder.get(), f), path, "encoding failed");
  drain_packets();
}

void Mp4Writer::Impl::drain_packets() {
  AVPacket* p = packet.get();
  for (;;) {
    const int status = avcodec_receive_packet(encoder.get(), p);
    if (status == AVERROR(EAGAIN) || status == AVERROR_EOF) return;
    check_av(status, path, "encoding failed");
    p->duration = 1;  // one frame: the MP4's length counts the last frame's too
    av_packet_rescale_ts(p, encoder->time_base, stream->time_base);
    p->stream_index = stream->index;
    check_av(av_interleaved_write_frame(muxer.get(), p), path, "write failed");
  }
}

// Lets the thread encode what it was handed, then joins it.
void Mp4Writer::Impl::stop_encoding_thread() {
  if (!encoding_thread.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex);
    closing = true;
  }
  changed.notify_all();
  encoding_thread.join();
}

// The encoder: yuv420p at fps, a keyframe every second, the encoder's own threads.
void Mp4Writer::Impl::make_encoder(const AVCodec* codec, const Mp4Settings& settings) {
  encoder.reset(avcodec_alloc_context3(codec));
  if (!encoder) throw std::bad_alloc();
  AVCodecContext* enc = encoder.get();
  enc->width = settings.width_px;
  enc->height = settings.height_px;
  enc->pix_fmt = AV_PIX_FMT_YUV420P;
  enc->time_base = AVRational{1, settings.fps};
  enc->framerate = AVRational{settings.fps, 1};
  enc->gop_size = settings.fps;
  enc->thread_count = 0;
  // the colour swscale produces: BT.601, limited range
  enc->colorspace = AVCOL_SPC_SMPTE170M;
  enc->color_primaries = AVCOL_PRI_SMPTE170M;
  enc->color_trc = AVCOL_TRC_SMPTE170M;
  enc->color_range = AVCOL_RANGE_MPEG;
}

// The muxer, writing `target` (the temp file, or "pipe:1"): an unwritable folder fails
// here, before any work.
void Mp4Writer::Impl::open_muxer(const std::string& target) {
  AVFormatContext* m = nullptr;
  const int status = avformat_alloc_output_context2(&m, nullptr, "mp4", target.c_str());
  if (status < 0 || !m) throw std::runtime_error("no MP4 muxer: " + av_error_text(status));
  muxer.reset(m);
  if (m->oformat->flags & AVFMT_GLOBALHEADER) encoder->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  const int opened = avio_open(&m->pb, target.c_str(), AVIO_FLAG_WRITE);
  if (opened < 0) throw InputError(path + ": cannot write (" + av_error_text(opened) + ")");
}

// Opens the encoder with the x264 settings, adds its stream and writes the MP4 header.
void Mp4Writer::Impl::open_encoder_and_write_header(const AVCodec* codec,
                                                    const Mp4Settings& settings, bool streamed) {
  AVCodecContext* enc = encoder.get();
  AVDictionary* encoder_options = nullptr;
  av_dict_set(&encoder_options, "preset", settings.x264_preset.c_str(), 0);
  av_dict_set(&encoder_options, "crf", std::to_string(settings.x264_crf).c_str(), 0);
  int status = avcodec_open2(enc, codec, &encoder_options);
  av_dict_free(&encoder_options);
  check_av(status, path, "cannot open the H.264 encoder");

  stream = avformat_new_stream(muxer.get(), nullptr);
  if (!stream) throw std::bad_alloc();
  stream->time_base = enc->time_base;
  check_av(avcodec_parameters_from_context(stream->codecpar, enc), path, "codec parameters");
  AVDictionary* muxer_options = nullptr;
  // a file: the index moved to the front (playable while downloading); a pipe cannot seek
  // back, so fragments, each with its own index (ffplay, ffmpeg and browsers read them)
  av_dict_set(&muxer_options, "movflags",
              streamed ? "frag_keyframe+empty_moov+default_base_moof" : "+faststart", 0);
  status = avformat_write_header(muxer.get(), &muxer_options);
  av_dict_free(&muxer_options);
  check_av(status, path, "cannot write the MP4 header");
}

// RGB (bottom-up) -> YUV 4:2:0 at the same size, into a reused frame.
void Mp4Writer::Impl::make_converter(int w, int h) {
  rgb_to_yuv.reset(sws_getContext(w, h, AV_PIX_FMT_RGB24, w, h, AV_PIX_FMT_YUV420P, SWS_BILINEAR,
                                  nullptr, nullptr, nullptr));
  frame = alloc_frame(w, h, AV_PIX_FMT_YUV420P);
  packet.reset(av_packet_alloc());
  if (!rgb_to_yuv || !packet) throw std::bad_alloc();
}

Mp4Writer::Mp4Writer(const std::string& path, const Mp4Settings& settings)
    : path_(path), impl_(std::make_unique<Impl>(path)) {
  const bool stream = path == "-";
  const std::string temp_path = stream ? "pipe:1" : impl_->temp_file->path();
  quiet_ffmpeg_log();
  const AVCodec* codec = checked_h264_encoder(path, settings);
  encoder_name_ = codec->name;

  Impl& x = *impl_;
  x.make_encoder(codec, settings);
  x.open_muxer(temp_path);
  x.open_encoder_and_write_header(codec, settings, stream);
  x.make_converter(settings.width_px, settings.height_px);

  // from here on only the encoding thread touches the FFmpeg objects, until finish()
  x.handed_over.resize(3 * static_cast<std::size_t>(settings.width_px) * settings.height_px);
  x.encoding_thread = std::thread([&x] { x.encoding_loop(); });
}

Mp4Writer::~Mp4Writer() = default;

void Mp4Writer::write_frame(const unsigned char* rgb_bottom_up) {
  Impl& x = *impl_;
  // wait until the encoding thread has taken the previous frame, then hand this one over
  {
    std::unique_lock<std::mutex> lock(x.mutex);
    x.changed.wait(lock, [&] { return !x.frame_waiting || x.failure; });
    if (x.failure) std::rethrow_exception(x.failure);
    std::memcpy(x.handed_over.data(), rgb_bottom_up, x.handed_over.size());
    x.frame_waiting = true;
  }
  x.changed.notify_all();
  ++frames_written_;
}

void Mp4Writer::finish() {
  Impl& x = *impl_;
  x.stop_encoding_thread();
  if (x.failure) std::rethrow_exception(x.failure);

  // flush the encoder's delayed frames, then the index (moved to the front: faststart)
  check_av(avcodec_send_frame(x.encoder.get(), nullptr), path_, "encoding failed");
  x.drain_packets();
  check_av(av_write_trailer(x.muxer.get()), path_, "cannot complete the MP4");
  check_av(avio_closep(&x.muxer->pb), path_, "write failed");

  if (x.temp_file) {
    if (std::rename(x.temp_file->path().c_str(), path_.c_str()) != 0) {
      throw InputError(path_ + ": cannot rename temp file into place (" + std::strerror(errno) +
                       ")");
    }
    x.temp_file->release();
  }
  impl_.reset();
}

}  // namespace pamsim
