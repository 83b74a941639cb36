#pragma once
// --stream's output: a ReadbackOutput's frames (drawn through the stream's warp, after the flash guard,
// read back without waiting) handed to a live stream (film/stream_sender.h) with their sound. In the
// gallery and the kiosk the frames are stamped with the wall clock from the first, so the stream runs at
// its 60 frames a second whatever the window's rate (a faster window's extra frames are skipped, a
// slower one's repeated by the receiver), and the sound is a copy of what the audio device plays, or,
// on a machine with no audio device, the synth rendered on the stream's own clock. A headless run's
// frames are stamped with their step (1/60 s each) and its sound is rendered offline.
#include "app/options.h"
#include "audio/engine.h"
#include "film/stream_sender.h"
#include "host/present/readback_output.h"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace vitrine::gpu {
class Device;
}

namespace vitrine::host {

inline constexpr double kStreamFps = 60.0;  // every stream's rate, the gallery's and a headless run's

// --stream, --stream-bitrate and --stream-latency for frames of `extent`.
film::StreamSettings streamSettings(const Options& options, VkExtent2D extent);

// Where a stream's sound comes from: each call appends the interleaved 48 kHz stereo frames that follow
// the last call's, up to about `seconds` on the stream's clock.
class StreamSound {
 public:
  virtual ~StreamSound() = default;
  virtual void until(double seconds, std::vector<float>& out) = 0;
};

class StreamSink final : public FrameSink {
 public:
  enum class Clock { Wall, Steps };  // the gallery's frames: when they come; a headless run's: their step
  StreamSink(const Options& options, VkExtent2D extent, std::unique_ptr<StreamSound> sound, Clock clock);
  void frame(const PublishedFrame& frame) override;
  Output::Health health() const override;
  // The sound up to `seconds`, then the stream ended (film::StreamSender::close); its last counts.
  film::StreamHealth finish(double seconds);

 private:
  film::StreamSender sender_;
  std::unique_ptr<StreamSound> sound_;
  Clock clock_;
  std::optional<std::chrono::steady_clock::time_point> start_;
  std::vector<uint8_t> packed_;  // a frame whose rows have padding, packed
  std::vector<float> stretch_;
};

// The gallery's stream output: the main window's size (rounded down to even sides, as 4:2:0 video
// needs), the whole frame square-on, the sound `audio` plays.
std::unique_ptr<Output> makeStreamOutput(const gpu::Device& device, const Options& options, VkExtent2D mainExtent,
                                         audio::AudioOutput& audio);

}  // namespace vitrine::host
