#include "rig/midi_clock.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace vitrine::rig {
namespace {

constexpr double kPaceChange = 0.04;    // the newest half beat's pace off the fit by this: the tempo changed
constexpr size_t kPaceGaps = MidiClock::kPulsesPerQuarter / 2;

}  // namespace

void MidiClock::realtime(double time, uint8_t status) {
  switch (status) {
    case 0xF8: return pulse(time);
    case 0xFA:  // start: from the top, the next pulse is beat 0
      pulses_ = 0, running_ = true, transportSeen_ = true, firstPulse_ = true;
      return;
    case 0xFB:  // continue: from the position held
      running_ = true, transportSeen_ = true, firstPulse_ = true;
      return;
    case 0xFC:
      running_ = false, transportSeen_ = true;
      return;
    default: return;
  }
}

void MidiClock::songPosition(int sixteenths) {
  pulses_ = int64_t(std::clamp(sixteenths, 0, 16383)) * (kPulsesPerQuarter / 4);
  firstPulse_ = true;
}

void MidiClock::pulse(double time) {
  const auto last = fit_.last();
  if (last && !(time >= *last)) return;  // time runs forward only (a NaN too is refused here)
  const bool afterLoss = last && time - *last > kLostSeconds;
  if (afterLoss) {
    // Back from a loss: the flywheel's position is where the beat is now, unless the transport moved.
    if (!firstPulse_ && (running_ || !transportSeen_) && heldInterval_ > 0.0)
      pulses_ += int64_t(std::llround((time - *last) / heldInterval_));
    fit_.clear();
  }
  const bool advancing = running_ || !transportSeen_;
  if (firstPulse_) firstPulse_ = false;
  else if (advancing && !afterLoss && last) ++pulses_;
  fit_.add(time);
  // A new tempo: refit from the pulses at the new pace rather than average the old one in for four beats.
  const auto fitted = fit_.interval();
  const auto recent = fit_.recentInterval(kPaceGaps);
  // Over 4 %, and over four standard errors of the recent mean given the pulses' own jitter, so that a
  // shaky clock is averaged rather than taken for a new tempo at every other pulse.
  const double threshold = fitted ? std::max(kPaceChange * *fitted, 4.0 * fit_.jitter() * std::sqrt(2.0) / kPaceGaps) : 0.0;
  if (fitted && recent && std::abs(*recent - *fitted) > threshold) {
    fit_.keepNewest(std::max<size_t>(fit_.newestNearer(*recent, *fitted), 2) + 1);
  }
  // An old pace's last gap kept at the front by a refit (jitter made it look new) is dropped once the
  // new pace is clear: one gap off by a few milliseconds would bias the line for four beats.
  if (const auto interval = fit_.interval(); interval && fit_.size() > 6)
    fit_.dropLeadingGapsOff(std::max(0.15 * *interval, 3.0 * std::sqrt(2.0) * fit_.jitter()));
  if (const auto interval = fit_.interval(); interval && *interval > 0.0) heldInterval_ = *interval;
}

std::optional<double> MidiClock::bpm() const {
  if (!(heldInterval_ > 0.0)) return std::nullopt;
  const double bpm = 60.0 / (heldInterval_ * kPulsesPerQuarter);
  if (bpm < kMinBpm || bpm > kMaxBpm) return std::nullopt;
  return bpm;
}

bool MidiClock::locked(double now) const {
  const auto last = fit_.last();
  return last && bpm() && now - *last <= kLostSeconds;
}

double MidiClock::beat(double now) const {
  double pulses = double(pulses_);
  const auto last = fit_.last();
  const bool advancing = running_ || !transportSeen_;
  if (advancing && !firstPulse_ && last && heldInterval_ > 0.0 && now > *last) pulses += (now - *last) / heldInterval_;
  return pulses / kPulsesPerQuarter;
}

ClockStatus MidiClock::status(double now) const {
  ClockStatus status{.name = "midi clock", .locked = locked(now), .bpm = bpm(), .jitterMs = jitterMs()};
  const auto last = fit_.last();
  if (!last) status.note = "waiting for clock";
  else if (!status.locked && bpm())
    status.note = fmt::format("lost {:.0f} s ago: own clock at {:.1f} BPM", now - *last, *bpm());
  else if (!status.locked) status.note = "lost: no tempo";
  else if (!running_ && transportSeen_) status.note = fmt::format("stopped at beat {:.2f}", beat(now));
  else status.note = fmt::format("running, beat {:.2f}", beat(now));
  return status;
}

}  // namespace vitrine::rig
