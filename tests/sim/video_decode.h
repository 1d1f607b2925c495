// video_decode.h: what a video test checks in a file pamsim wrote, read back independently
// through FFmpeg's demuxers and decoders: the codec, the size, every frame decoded and
// counted, and chosen frames as RGB (rows top-down) for pixel checks. Works for MP4 and for
// single PNG images.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "sim/render/av_handles.h"

namespace pamsim_test {

struct DecodedVideo {
  bool opened = false;
  std::string codec;  // "h264", "png", ...
  int width = 0;
  int height = 0;
  int frames = 0;                               // frames decoded
  std::vector<std::vector<unsigned char>> rgb;  // frames kept, 3 * width * height each
};

// Decodes all of `path`; keeps the RGB of the first `keep_frames` frames.
inline DecodedVideo decode_video(const std::string& path, int keep_frames = 0) {
  using namespace pamsim;
  DecodedVideo v;
  AVFormatContext* raw = nullptr;
  if (avformat_open_input(&raw, path.c_str(), nullptr, nullptr) < 0) return v;
  AvInputContextPtr input(raw);
  if (avformat_find_stream_info(input.get(), nullptr) < 0) return v;
  const int stream = av_find_best_stream(input.get(), AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (stream < 0) return v;
  const AVCodecParameters* par = input->streams[stream]->codecpar;
  const AVCodec* codec = avcodec_find_decoder(par->codec_id);
  if (!codec) return v;
  AvCodecContextPtr decoder(avcodec_alloc_context3(codec));
  avcodec_parameters_to_context(decoder.get(), par);
  if (avcodec_open2(decoder.get(), codec, nullptr) < 0) return v;
  v.opened = true;
  v.codec = codec->name;
  v.width = par->width;
  v.height = par->height;

  AvPacketPtr packet(av_packet_alloc());
  AvFramePtr frame(av_frame_alloc());
  SwsContextPtr to_rgb;
  auto receive_all = [&] {
    while (avcodec_receive_frame(decoder.get(), frame.get()) >= 0) {
      if (v.frames < keep_frames) {
        to_rgb.reset(sws_getContext(
            frame->width, frame->height, static_cast<AVPixelFormat>(frame->format), frame->width,
            frame->height, AV_PIX_FMT_RGB24, SWS_POINT, nullptr, nullptr, nullptr));
        std::vector<unsigned char> rgb(3 * static_cast<std::size_t>(v.width) * v.height);
        uint8_t* dst[1] = {rgb.data()};
        const int dst_stride[1] = {3 * v.width};
        sws_scale(to_rgb.get(), frame->data, frame->linesize, 0, frame->height, dst, dst_stride);
        v.rgb.push_back(std::move(rgb));
      }
      ++v.frames;
    }
  };
  while (av_read_frame(input.get(), packet.get()) >= 0) {
    if (packet->stream_index == stream) avcodec_send_packet(decoder.get(), packet.get());
    av_packet_unref(packet.get());
    receive_all();
  }
  avcodec_send_packet(decoder.get(), nullptr);  // flush delayed frames
  receive_all();
  return v;
}

}  // namespace pamsim_test
