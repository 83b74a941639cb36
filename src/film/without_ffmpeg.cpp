// A build without FFmpeg (VITRINE_WITH_FILM=OFF, the GPU machine's packed binary): everything about a
// film but its encoding is there (names, codecs, options are still checked), and an encoder says why
// it cannot start.
#include "core/error.h"
#include "film/stream_sender.h"
#include "film/video_encoder.h"

#include <fmt/format.h>

#include <cstdio>

namespace vitrine::film {

struct VideoEncoder::State {};

VideoEncoder::VideoEncoder(const std::filesystem::path& target, const FilmFormat&, uint32_t, uint32_t, double) {
  throw Error(fmt::format("Cannot write {}: this build encodes no films (built with VITRINE_WITH_FILM=OFF); record "
                          "into a folder and run vitrine encode on it with a build that has FFmpeg.",
                          target.string()));
}
VideoEncoder::~VideoEncoder() = default;
void VideoEncoder::addFrame(const ImageRgba&) {}
void VideoEncoder::addFrame(const Picture&) {}
uint32_t VideoEncoder::frames() const { return 0; }
void VideoEncoder::addSoundTrack() {}
bool VideoEncoder::hasSoundTrack() const { return false; }
void VideoEncoder::addSound(std::span<const float>) {}
void VideoEncoder::finish() {}
void VideoEncoder::addDisplay(std::span<const std::byte>) {}
DisplayLayout VideoEncoder::layout() const { return DisplayLayout::Rgb24; }
const std::string& VideoEncoder::encoderChoice() const {
  static const std::string none = "no encoder (a build without FFmpeg)";
  return none;
}
VideoEncoder::StageTimes VideoEncoder::times() const { return {}; }

std::string streamMuxer(std::string_view url) {
  throw Error(fmt::format("Cannot stream to {}: this build streams nothing (built with VITRINE_WITH_FILM=OFF).", url));
}

struct StreamSender::Worker {
  StreamSettings settings;
  StreamHealth health;
};
StreamSender::StreamSender(const StreamSettings& settings)
    : worker_(std::make_unique<Worker>(Worker{settings, {}})) {
  try {
    streamMuxer(settings.url);
  } catch (const Error& e) {
    worker_->health.line = e.what();
    worker_->health.stopped = true;
    std::fprintf(stderr, "vitrine: %s The run goes on without it.\n", e.what());
  }
}
StreamSender::~StreamSender() = default;
bool StreamSender::pushFrame(std::span<const uint8_t>, double) { return false; }
void StreamSender::pushSound(std::span<const float>) {}
void StreamSender::close() {}
StreamHealth StreamSender::health() const { return worker_->health; }
const StreamSettings& StreamSender::settings() const { return worker_->settings; }

}  // namespace vitrine::film
