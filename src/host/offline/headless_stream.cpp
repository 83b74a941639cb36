#include "host/offline/headless_stream.h"

#include "host/offline/record_shared.h"
#include "host/present/stream_sink.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace vitrine::host {
namespace {

// The run's sound, rendered offline as a film's: a stretch reaches kLag behind the frames, since a
// scene stamps a sound with the time its cause happened, which it may learn a few frames later
// (FilmSound says more); the last stretch reaches the end.
class RunSound final : public StreamSound {
 public:
  RunSound(const audio::OfflineAudio& sound, const LiveLink* live, double start, double seconds)
      : film_(sound, live, start, seconds), seconds_(seconds) {}
  void until(double seconds, std::vector<float>& out) override {
    static constexpr double kLag = 0.1;
    const double reach = seconds >= seconds_ ? seconds_ : seconds - kLag;
    const std::span<const float> next = film_.next(std::max<int64_t>(0, audio::toSamples(reach)));
    out.insert(out.end(), next.begin(), next.end());
  }

 private:
  FilmSound film_;
  double seconds_;
};

}  // namespace

HeadlessStream::HeadlessStream(const gpu::Device& device, const Options& options, VkExtent2D size,
                               const std::optional<maths::OutputWarp>& warp, const audio::OfflineAudio& sound,
                               const LiveLink* live, uint32_t frames) {
  const double seconds = double(frames) / kStreamFps;
  auto sink = std::make_unique<StreamSink>(options, size, std::make_unique<RunSound>(sound, live, options.time, seconds),
                                           StreamSink::Clock::Steps);
  sink_ = sink.get();
  output_ = std::make_unique<ReadbackOutput>(device, "stream", warp.value_or(maths::OutputWarp{}), size, std::move(sink));
}

HeadlessStream::~HeadlessStream() = default;

void HeadlessStream::finish(uint32_t rendered) {
  const film::StreamHealth health = sink_->finish(double(rendered) / kStreamFps);
  std::printf("stream: %llu frames sent, %llu dropped (the encoder behind), %llu while not connected, %llu "
              "reconnections; %s\n",
              static_cast<unsigned long long>(health.sent), static_cast<unsigned long long>(health.dropped),
              static_cast<unsigned long long>(health.disconnected),
              static_cast<unsigned long long>(health.reconnects), health.line.c_str());
}

}  // namespace vitrine::host
