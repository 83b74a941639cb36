#pragma once
// A copy of the sound as it is played, for a live stream: the audio callback writes each block it
// renders, the frame loop reads what has come. Neither side locks or waits (an SpscQueue of stereo
// frames); what the reader has not taken when the ring is full is dropped and counted, never
// waited for.
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "audio/spsc_queue.h"

namespace vitrine::audio {

class SoundTap {
 public:
  static constexpr size_t kFrames = size_t(1) << 15;  // 0.68 s at 48 kHz

  // Producer (the audio thread): interleaved stereo frames.
  void write(const float* stereo, size_t frames) {
    for (size_t i = 0; i < frames; ++i)
      if (!ring_.push({stereo[2 * i], stereo[2 * i + 1]})) {
        dropped_.fetch_add(frames - i, std::memory_order_relaxed);
        return;
      }
  }
  // Consumer (the frame loop): appends every frame that has come to `out`, interleaved.
  void read(std::vector<float>& out) {
    while (const std::array<float, 2>* frame = ring_.front()) {
      out.push_back((*frame)[0]);
      out.push_back((*frame)[1]);
      ring_.pop();
    }
  }
  uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  SpscQueue<std::array<float, 2>, kFrames> ring_;
  std::atomic<uint64_t> dropped_{0};
};

}  // namespace vitrine::audio
