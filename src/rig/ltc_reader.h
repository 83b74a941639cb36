#pragma once
// LTC (linear timecode, SMPTE 12M) read from sound by libltc: the position of the show's timecode in
// a stream of samples, frame-exact. A frame's bits begin as its video frame does, so the frame
// showing at the stream's end is the last decoded frame plus the whole frames of samples since its
// first bit. The rate is told from the samples a frame spans (24, 25 or 30 a second) and its
// drop-frame flag (29.97 drop-frame); direction from libltc (a tape played backwards).
//
// Only the samples matter, so the --audio-in file (fed as the simulation clock plays it) and the live
// capture give the same answers. Labels that cannot be (hours over 23, a frame over the rate, a
// dropped 29.97 label) are refused with one line in trouble(). Pure with respect to time: it counts
// samples, never reads a clock.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rig/clock_status.h"
#include "rig/mtc.h"
#include "rig/pulse_fit.h"

struct LTCFrameExt;  // libltc's, kept out of this header

namespace vitrine::rig {

class LtcReader {
 public:
  // A frame is decoded as the next begins: no frame for this many frames' samples since the last one
  // began is a stopped timecode or a pulled cable. The position then holds where it had counted to.
  static constexpr double kLostFrames = 3.0;

  explicit LtcReader(double sampleRate);
  ~LtcReader();
  LtcReader(const LtcReader&) = delete;
  LtcReader& operator=(const LtcReader&) = delete;

  // Mono samples in -1..1 that follow those given before.
  void push(std::span<const float> samples);

  // The frame at the end of the samples given; none before the first frame decoded.
  std::optional<TimecodePosition> position() const;
  bool locked() const;  // a frame decoded within kLostFrames of the stream's end
  uint64_t frames() const { return decoded_; }  // frames decoded
  uint64_t jumps() const { return jumps_; }     // frames that did not follow the one before
  uint64_t refused() const { return refused_; }
  const std::string& trouble() const { return trouble_; }
  double jitterMs() const { return fit_.jitter() * 1000.0; }
  ClockStatus status() const;

 private:
  void take(const ::LTCFrameExt& frame);
  struct Decoder;
  std::unique_ptr<Decoder> decoder_;
  double sampleRate_;
  uint64_t stream_ = 0;          // samples given so far
  std::vector<float> scratch_;   // libltc writes through a non-const pointer
  std::optional<int64_t> frame_;  // the last decoded frame's count
  int64_t frameStart_ = 0;       // the stream sample of its first bit
  double samplesPerFrame_ = 0.0;  // smoothed over the frames decoded
  FrameRate rate_ = FrameRate::Fps25;
  int direction_ = 0;
  double volumeDb_ = 0.0;
  PulseFit fit_{32};
  uint64_t decoded_ = 0, jumps_ = 0, refused_ = 0;
  std::string trouble_;
};

}  // namespace vitrine::rig
