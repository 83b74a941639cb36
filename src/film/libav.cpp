#include "film/libav.h"

#include <fmt/format.h>

#include <cstdarg>
#include <cstdio>
#include <new>

#include "core/error.h"
#include "film/film_format.h"

namespace vitrine::film {

std::string avErrorText(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  av_strerror(code, text, sizeof text);
  return text;
}

int checkAv(int code, const std::string& target, std::string_view what) {
  if (code < 0) throw Error(fmt::format("Cannot write {}: {} failed: {}.", target, what, avErrorText(code)));
  return code;
}

void encodeInto(AVCodecContext& codec, const AVFrame* frame, AVFormatContext& output, AVStream& stream,
                AVPacket& packet, const std::string& target, std::string_view what) {
  checkAv(avcodec_send_frame(&codec, frame), target, fmt::format("encoding {}", what));
  for (;;) {
    const int received = avcodec_receive_packet(&codec, &packet);
    if (received == AVERROR(EAGAIN) || received == AVERROR_EOF) return;
    checkAv(received, target, fmt::format("encoding {}", what));
    av_packet_rescale_ts(&packet, codec.time_base, stream.time_base);
    packet.stream_index = stream.index;
    checkAv(av_interleaved_write_frame(&output, &packet), target, fmt::format("writing {}", what));
  }
}

FramePtr makeFrame() {
  FramePtr frame(av_frame_alloc());
  if (!frame) throw std::bad_alloc();
  return frame;
}

PacketPtr makePacket() {
  PacketPtr packet(av_packet_alloc());
  if (!packet) throw std::bad_alloc();
  return packet;
}

OutputPtr openOutput(const std::string& muxer, const std::string& path, const std::string& target) {
  AVFormatContext* raw = nullptr;
  checkAv(avformat_alloc_output_context2(&raw, nullptr, muxer.c_str(), path.c_str()), target, "choosing the muxer");
  OutputPtr output(raw);
  checkAv(avio_open(&output->pb, path.c_str(), AVIO_FLAG_WRITE), target, "opening the file");
  return output;
}

// MP4 and QuickTime carry the colour tags in a 'colr' box only when asked to (Matroska always does); an
// MP4, for the web, has its index first, so players start before the whole file has arrived.
AVDictionary* muxerOptions(const FilmFormat& format) {
  AVDictionary* options = nullptr;
  if (format.container == Container::Mov) av_dict_set(&options, "movflags", "+write_colr", 0);
  if (format.container == Container::Mp4) av_dict_set(&options, "movflags", "+write_colr+faststart", 0);
  return options;
}

namespace {

thread_local LibavMessages* capturing = nullptr;

void logOrKeep(void* object, int level, const char* format, va_list args) {
  if (!capturing || level > av_log_get_level()) return av_log_default_callback(object, level, format, args);
  char line[512];
  std::vsnprintf(line, sizeof line, format, args);
  capturing->keep(line);
}

}  // namespace

void quietLibav() {
  av_log_set_level(AV_LOG_ERROR);
  av_log_set_callback(logOrKeep);
}

LibavMessages::LibavMessages() : outer_(capturing) {
  quietLibav();
  capturing = this;
}

LibavMessages::~LibavMessages() { capturing = outer_; }

void LibavMessages::keep(std::string_view line) {
  while (!line.empty() && (line.back() == '\n' || line.back() == ' ' || line.back() == '.')) line.remove_suffix(1);
  if (line.empty()) return;
  if (!text_.empty()) text_ += "; ";
  text_ += line;
}

void tagColour(AVCodecContext& codec, bool rgb, bool fullRange) {
  codec.color_primaries = AVCOL_PRI_BT709;
  codec.color_trc = AVCOL_TRC_IEC61966_2_1;
  codec.colorspace = rgb ? AVCOL_SPC_RGB : AVCOL_SPC_BT709;
  codec.color_range = fullRange ? AVCOL_RANGE_JPEG : AVCOL_RANGE_MPEG;
}

ScalerPtr rgbToYuv(uint32_t width, uint32_t height, AVPixelFormat source, AVPixelFormat yuv, bool fullRange,
                   const std::string& target) {
  ScalerPtr scaler(sws_getContext(int(width), int(height), source, int(width), int(height), yuv,
                                  SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr));
  if (!scaler)
    throw Error(fmt::format("Cannot write {}: swscale cannot convert {} to {}.", target, av_get_pix_fmt_name(source),
                            av_get_pix_fmt_name(yuv)));
  const int* bt709 = sws_getCoefficients(SWS_CS_ITU709);
  sws_setColorspaceDetails(scaler.get(), bt709, 1, bt709, fullRange ? 1 : 0, 0, 1 << 16, 1 << 16);
  return scaler;
}

}  // namespace vitrine::film
