#include "rig/mtc.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace vitrine::rig {
namespace {

constexpr FrameRate kRates[4] = {FrameRate::Fps24, FrameRate::Fps25, FrameRate::Fps2997Drop, FrameRate::Fps30};

// The distance between two positions in quarter frames, through midnight where that is shorter.
int64_t quartersApart(int64_t a, int64_t b, FrameRate rate) {
  const int64_t day = framesPerDay(rate) * 4;
  int64_t d = (a - b) % day;
  if (d < 0) d += day;
  return std::min(d, day - d);
}

std::string labelText(int h, int m, int s, int f) { return fmt::format("{:02}:{:02}:{:02}:{:02}", h, m, s, f); }

}  // namespace

void Mtc::refuse(std::string why) {
  ++refused_;
  trouble_ = std::move(why);
}

void Mtc::anchor(int64_t frames, FrameRate rate, int quarters) {
  const int64_t wanted = frames * 4 + quarters;
  // Where the pieces had counted to, against where the cycle says: over a quarter apart is a locate.
  if (quarters_ && cycleKnown_ && rate == rate_ && quartersApart(*quarters_, wanted, rate) > 1) ++jumps_;
  quarters_ = wanted;
  rate_ = rate;
}

void Mtc::quarterFrame(double time, uint8_t data) {
  if (data > 0x7F) return refuse(fmt::format("quarter frame data 0x{:02X} is not a data byte", data));
  if (!(time >= lastTime_ - 1e-9)) return refuse("a quarter frame earlier than the one before");
  const int piece = data >> 4;
  const bool forwards = lastPiece_ >= 0 && piece == (lastPiece_ + 1) % 8;
  const bool backwards = lastPiece_ >= 0 && piece == (lastPiece_ + 7) % 8;
  const bool gap = time - lastTime_ > kLostSeconds;
  if (!gap && (forwards || backwards)) {
    const int direction = forwards ? 1 : -1;
    if (direction_ != 0 && direction != direction_) seen_ = 0, fit_.clear();  // turned round
    direction_ = direction;
    if (quarters_) *quarters_ += direction;
    fit_.add(time);
  } else {
    // A new run (or the pieces broke step): the position waits for a whole cycle in order.
    if (lastPiece_ >= 0 && !gap) refuse(fmt::format("quarter frame piece {} after piece {}", piece, lastPiece_));
    seen_ = 0, direction_ = 0, cycleKnown_ = false;
    fit_.clear();
    fit_.add(time);
  }
  lastPiece_ = piece, lastTime_ = time;
  // A cycle starts afresh at piece 0 forwards, at piece 7 backwards.
  if ((direction_ >= 0 && piece == 0) || (direction_ < 0 && piece == 7)) seen_ = 0;
  nibbles_[piece] = data & 0x0F;
  seen_ |= uint8_t(1u << piece);
  const bool complete = seen_ == 0xFF && ((direction_ > 0 && piece == 7) || (direction_ < 0 && piece == 0));
  if (!complete) return;
  const int frame = nibbles_[0] | (nibbles_[1] & 1) << 4, second = nibbles_[2] | (nibbles_[3] & 3) << 4;
  const int minute = nibbles_[4] | (nibbles_[5] & 3) << 4, hour = nibbles_[6] | (nibbles_[7] & 1) << 4;
  const FrameRate rate = kRates[(nibbles_[7] >> 1) & 3];
  const auto count = frameCount({hour, minute, second, frame}, rate);
  if (!count)
    return refuse(fmt::format("impossible timecode {} at {} fps", labelText(hour, minute, second, frame), rateName(rate)));
  anchor(*count, rate, piece);
  cycleKnown_ = true;
}

void Mtc::sysex(std::span<const uint8_t> body) {
  // Universal real time (7F), any device, MTC (01) full frame (01): hh mm ss ff.
  if (body.size() < 4 || body[0] != 0x7F || body[2] != 0x01 || body[3] != 0x01) return;
  if (body.size() != 8) return refuse(fmt::format("an MTC full frame of {} bytes, not 10", body.size() + 2));
  const int hour = body[4] & 0x1F, minute = body[5], second = body[6], frame = body[7];
  const FrameRate rate = kRates[(body[4] >> 5) & 3];
  const auto count = frameCount({hour, minute, second, frame}, rate);
  if (!count)
    return refuse(fmt::format("impossible full-frame timecode {} at {} fps", labelText(hour, minute, second, frame),
                              rateName(rate)));
  // A locate: the transport is parked on this frame until quarter frames run again.
  if (quarters_ && (rate != rate_ || quartersApart(*quarters_, *count * 4, rate) > 1)) ++jumps_;
  quarters_ = *count * 4;
  rate_ = rate;
  seen_ = 0, lastPiece_ = -1, direction_ = 0, cycleKnown_ = false;
  fit_.clear();
}

std::optional<TimecodePosition> Mtc::position() const {
  if (!quarters_) return std::nullopt;
  const int64_t day = framesPerDay(rate_) * 4;
  int64_t q = *quarters_ % day;
  if (q < 0) q += day;
  return TimecodePosition{q / 4, rate_, double(q % 4) / 4.0, direction_};
}

bool Mtc::locked(double now) const { return quarters_ && cycleKnown_ && now - lastTime_ <= kLostSeconds; }

ClockStatus Mtc::status(double now) const {
  ClockStatus status{.name = "mtc", .locked = locked(now), .jitterMs = jitterMs()};
  const auto at = position();
  if (at) {
    status.seconds = at->seconds();
    status.timecode = formatTimecode(at->label());
  }
  if (!at) status.note = "waiting for timecode";
  else if (status.locked)
    status.note = fmt::format("{} fps, {}", rateName(at->rate), direction_ < 0 ? "backwards" : "forwards");
  else if (lastPiece_ < 0 && !cycleKnown_) status.note = fmt::format("{} fps, parked (full frame)", rateName(at->rate));
  else status.note = fmt::format("{} fps, stopped {:.0f} s ago", rateName(at->rate), now - lastTime_);
  if (!trouble_.empty()) status.note += "; last refused: " + trouble_;
  return status;
}

}  // namespace vitrine::rig
