#pragma once
// A headless run's --stream: a ReadbackOutput beside the run's own output (its warp, after the flash
// guard, converted to 8-bit sRGB on the GPU), each frame stamped with its step (1/60 s), the run paced
// at 60 frames a second of wall time by its caller, and the run's sound (the scene's, rendered offline
// a stretch at a time, and --audio-in's music) on the same clock.
#include "app/options.h"
#include "audio/engine.h"
#include "host/live_link.h"
#include "host/present/readback_output.h"

#include <cstdint>
#include <memory>
#include <optional>

namespace vitrine::gpu {
class Device;
}

namespace vitrine::host {

class StreamSink;

class HeadlessStream {
 public:
  // `sound` and `live` must outlive this; the run is `frames` frames of 1/60 s from options.time.
  HeadlessStream(const gpu::Device& device, const Options& options, VkExtent2D size,
                 const std::optional<maths::OutputWarp>& warp, const audio::OfflineAudio& sound, const LiveLink* live,
                 uint32_t frames);
  ~HeadlessStream();
  Output& output() { return *output_; }  // for Offscreen::addOutput
  // The sound up to the last frame, the stream ended, and its counts on stdout.
  void finish(uint32_t rendered);

 private:
  std::unique_ptr<ReadbackOutput> output_;
  StreamSink* sink_;
};

}  // namespace vitrine::host
