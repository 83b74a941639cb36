#pragma once
// MIDI timecode: quarter frames (0xF1, eight pieces over two frames, each a nibble of the label and
// the rate) while the show's transport runs, and full frames (SysEx F0 7F dev 01 01 hh mm ss ff F7)
// when it locates. Frame-exact: piece k of the cycle whose label is T arrives as frame T plus k
// quarters begins, so the position moves a quarter frame a piece, forwards when the pieces come
// 0..7, backwards when they come 7..0. A cycle that completes somewhere other than where the pieces
// had counted to is a jump (the show controller located). Impossible labels (hours over 23, a frame
// over the rate, a dropped 29.97 label), pieces out of order and malformed SysEx are refused with one
// line in trouble() and never move the position. Pure logic on the times it is given.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include "rig/clock_status.h"
#include "rig/pulse_fit.h"
#include "rig/timecode.h"

namespace vitrine::rig {

// Where a timecode source is: a frame count (since 00:00:00:00) and the quarters of a frame past it.
struct TimecodePosition {
  int64_t frames = 0;
  FrameRate rate = FrameRate::Fps25;
  double fraction = 0.0;  // 0..1 of the next frame
  int direction = 0;      // +1 forwards, -1 backwards, 0 parked (a full frame, or not moving)
  double seconds() const { return secondsOf(frames, rate) + fraction / realFps(rate); }
  Timecode label() const { return labelOf(frames, rate); }
};

class Mtc {
 public:
  // A quarter frame is 10 ms apart at 24 fps: a quarter second without one is a stopped transport or
  // a lost cable.
  static constexpr double kLostSeconds = 0.25;

  void quarterFrame(double time, uint8_t data);
  // A SysEx body (between F0 and F7): full frames are read, any other SysEx ignored.
  void sysex(std::span<const uint8_t> body);

  // None until a cycle of quarter frames or a full frame has given a label.
  std::optional<TimecodePosition> position() const;
  bool locked(double now) const;  // quarter frames arriving, in order, on a known label
  uint64_t jumps() const { return jumps_; }
  uint64_t refused() const { return refused_; }
  const std::string& trouble() const { return trouble_; }
  double jitterMs() const { return fit_.jitter() * 1000.0; }
  ClockStatus status(double now) const;

 private:
  void refuse(std::string why);
  void anchor(int64_t frames, FrameRate rate, int quarters);
  uint8_t nibbles_[8] = {};
  uint8_t seen_ = 0;      // the pieces of this cycle received so far, a bit each
  int lastPiece_ = -1;
  int direction_ = 0;
  std::optional<int64_t> quarters_;  // the position in quarter frames
  FrameRate rate_ = FrameRate::Fps25;
  double lastTime_ = -1e300;  // the last quarter frame's arrival
  bool cycleKnown_ = false;   // a complete cycle has anchored the position since the last break
  PulseFit fit_{32};
  uint64_t jumps_ = 0, refused_ = 0;
  std::string trouble_;
};

}  // namespace vitrine::rig
