#include "host/offline/headless_stream.h"

#include "image/image_io.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace vitrine::host {
namespace {

constexpr double kFps = 60.0;

film::StreamSettings streamSettings(const Options& options, VkExtent2D size) {
  film::StreamSettings settings;
  settings.url = options.stream;
  settings.width = size.width;
  settings.height = size.height;
  settings.fps = kFps;
  settings.bitrate = options.streamBitrate;
  settings.latencyMs = int(options.streamLatencyMs);
  return settings;
}

}  // namespace

HeadlessStream::HeadlessStream(const Options& options, VkExtent2D size, const audio::OfflineAudio& sound,
                               const LiveLink* live, uint32_t frames)
    : sender_(streamSettings(options, size)), sound_(sound, live, options.time, double(frames) / kFps) {}

void HeadlessStream::frame(Offscreen& offscreen, uint32_t index) {
  const std::vector<uint8_t> rgba = srgb8(offscreen.readback());
  sender_.pushFrame(rgba, double(index) / kFps);
  sender_.pushSound(sound_.next(std::max<int64_t>(0, audio::toSamples(double(index + 1) / kFps - kSoundLag))));
}

void HeadlessStream::finish(uint32_t rendered) {
  sender_.pushSound(sound_.next(audio::toSamples(double(rendered) / kFps)));
  sender_.close();
  const film::StreamHealth health = sender_.health();
  std::printf("stream: %llu frames sent, %llu dropped (the encoder behind), %llu while not connected, %llu "
              "reconnections; %s\n",
              static_cast<unsigned long long>(health.sent), static_cast<unsigned long long>(health.dropped),
              static_cast<unsigned long long>(health.disconnected),
              static_cast<unsigned long long>(health.reconnects), health.line.c_str());
}

}  // namespace vitrine::host
