// av_handles.h: owning handles for FFmpeg's C objects (codec, format, scaler contexts,
// frames, packets), so every exit path frees them; FFmpeg's error codes as text or as an
// exception, and its log silenced.
// Included only by .cc files that use FFmpeg (and the video tests), never by a public header.
#pragma once

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/error.h>
#include <libavutil/log.h>
#include <libswscale/swscale.h>
}

#include <memory>
#include <new>
#include <stdexcept>
#include <string>

namespace pamsim {

struct AvCodecContextDeleter {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct AvFrameDeleter {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct AvPacketDeleter {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct SwsContextDeleter {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};
// a muxer: closes its file if open, then frees it
struct AvOutputContextDeleter {
  void operator()(AVFormatContext* f) const {
    if (f->pb && !(f->oformat->flags & AVFMT_NOFILE)) avio_closep(&f->pb);
    avformat_free_context(f);
  }
};
// a demuxer opened by avformat_open_input
struct AvInputContextDeleter {
  void operator()(AVFormatContext* f) const { avformat_close_input(&f); }
};

using AvCodecContextPtr = std::unique_ptr<AVCodecContext, AvCodecContextDeleter>;
using AvFramePtr = std::unique_ptr<AVFrame, AvFrameDeleter>;
using AvPacketPtr = std::unique_ptr<AVPacket, AvPacketDeleter>;
using SwsContextPtr = std::unique_ptr<SwsContext, SwsContextDeleter>;
using AvOutputContextPtr = std::unique_ptr<AVFormatContext, AvOutputContextDeleter>;
using AvInputContextPtr = std::unique_ptr<AVFormatContext, AvInputContextDeleter>;

// A frame of `format` with its own buffer, or std::bad_alloc.
inline AvFramePtr alloc_frame(int width, int height, AVPixelFormat format) {
  AvFramePtr frame(av_frame_alloc());
  if (!frame) throw std::bad_alloc();
  frame->format = format;
  frame->width = width;
  frame->height = height;
  if (av_frame_get_buffer(frame.get(), 0) < 0) throw std::bad_alloc();
  return frame;
}

// FFmpeg prints nothing: pamsim reports its errors itself, one line each (av_error_text).
inline void quiet_ffmpeg_log() { av_log_set_level(AV_LOG_QUIET); }

// FFmpeg's message for an error code (av_err2str is a C-only macro).
inline std::string av_error_text(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = "";
  av_strerror(code, text, sizeof(text));
  return text;
}

// An FFmpeg call that must succeed: std::runtime_error "<where>: <what>: <FFmpeg's message>".
inline void check_av(int status, const std::string& where, const char* what) {
  if (status < 0) throw std::runtime_error(where + ": " + what + ": " + av_error_text(status));
}

}  // namespace pamsim
