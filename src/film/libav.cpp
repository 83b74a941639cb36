#include "film/libav.h"

#include <fmt/format.h>

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

void quietLibav() { av_log_set_level(AV_LOG_ERROR); }

}  // namespace vitrine::film
