// A build without FFmpeg (VITRINE_WITH_FILM=OFF, the GPU machine's packed binary): everything about a
// film but its encoding is there (names, codecs, options are still checked), and an encoder says why
// it cannot start.
#include "core/error.h"
#include "film/video_encoder.h"

#include <fmt/format.h>

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

}  // namespace vitrine::film
