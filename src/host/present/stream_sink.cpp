#include "host/present/stream_sink.h"

#include "audio/synth.h"

#include <algorithm>
#include <cstring>
#include <span>

namespace vitrine::host {
namespace {

// The gallery's sound on the stream's clock: without an audio device the synth rendered up to now;
// with one, the copy of what it played, kept within kSlack of now (silence over a pause, the excess of
// a device clock that runs fast dropped), so the sound never drifts from the picture.
class GallerySound final : public StreamSound {
 public:
  explicit GallerySound(audio::AudioOutput& audio) : audio_(audio) { audio_.tap(); }  // the copy starts now

  void until(double seconds, std::vector<float>& out) override {
    static constexpr int64_t kSlack = 4800;  // 0.1 s: the device's buffers and a frame's jitter
    const int64_t due = audio::toSamples(seconds);
    const size_t from = out.size();
    if (audio_.silent()) {
      out.resize(from + size_t(std::max<int64_t>(0, due - given_)) * 2);
      audio_.renderUnheard(out.data() + from, (out.size() - from) / 2);
    } else {
      audio_.tap().read(out);
      const int64_t after = given_ + int64_t((out.size() - from) / 2);
      if (after < due - kSlack || after > due + kSlack) out.resize(from + size_t(std::max<int64_t>(0, due - given_)) * 2, 0.0f);
    }
    given_ += int64_t((out.size() - from) / 2);
  }

 private:
  audio::AudioOutput& audio_;
  int64_t given_ = 0;  // frames of sound given to the stream
};

}  // namespace

film::StreamSettings streamSettings(const Options& options, VkExtent2D extent) {
  film::StreamSettings settings;
  settings.url = options.stream;
  settings.width = extent.width;
  settings.height = extent.height;
  settings.fps = kStreamFps;
  settings.bitrate = options.streamBitrate;
  settings.latencyMs = int(options.streamLatencyMs);
  return settings;
}

StreamSink::StreamSink(const Options& options, VkExtent2D extent, std::unique_ptr<StreamSound> sound, Clock clock)
    : sender_(streamSettings(options, extent)), sound_(std::move(sound)), clock_(clock) {}

void StreamSink::frame(const PublishedFrame& frame) {
  const auto now = std::chrono::steady_clock::now();
  if (!start_) start_ = now;
  const double seconds = clock_ == Clock::Wall ? std::chrono::duration<double>(now - *start_).count()
                                               : double(frame.index) / kStreamFps;
  const size_t row = size_t(frame.width) * 4;
  std::span<const uint8_t> rgba(reinterpret_cast<const uint8_t*>(frame.bytes.data()), row * frame.height);
  if (frame.stride != row) {
    packed_.resize(row * frame.height);
    for (uint32_t y = 0; y < frame.height; ++y)
      std::memcpy(packed_.data() + y * row, frame.bytes.data() + size_t(y) * frame.stride, row);
    rgba = packed_;
  }
  sender_.pushFrame(rgba, seconds);
  stretch_.clear();
  sound_->until(seconds, stretch_);
  sender_.pushSound(stretch_);
}

Output::Health StreamSink::health() const {
  const film::StreamHealth h = sender_.health();
  Output::Health health;
  health.kind = "stream";
  health.line = h.line;
  health.frames = h.sent;
  health.dropped = h.dropped + h.disconnected;
  health.connected = h.connected;
  return health;
}

film::StreamHealth StreamSink::finish(double seconds) {
  stretch_.clear();
  sound_->until(seconds, stretch_);
  sender_.pushSound(stretch_);
  sender_.close();
  return sender_.health();
}

std::unique_ptr<Output> makeStreamOutput(const gpu::Device& device, const Options& options, VkExtent2D mainExtent,
                                         audio::AudioOutput& audio) {
  const VkExtent2D extent{std::max(2u, mainExtent.width & ~1u), std::max(2u, mainExtent.height & ~1u)};
  return std::make_unique<ReadbackOutput>(
      device, "stream", maths::OutputWarp{}, extent,
      std::make_unique<StreamSink>(options, extent, std::make_unique<GallerySound>(audio), StreamSink::Clock::Wall));
}

}  // namespace vitrine::host
