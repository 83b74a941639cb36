#pragma once
// MIDI clock as a DJ's software or a drum machine sends it: 0xF8 twenty-four times a quarter note,
// 0xFA start, 0xFB continue, 0xFC stop, 0xF2 song position (in sixteenths). It keeps the tempo (a line
// fitted through the last four beats' pulses; when the newest half beat's pace is over 4 % off it, refitted
// from the pulses at the new pace), the jitter (the pulses' spread around that line) and the beat position.
//
// Pulses with no start, stop or continue ever seen count as running (many programs send only the
// pulses). With no pulse for kLostSeconds the clock is lost: the beat runs on at the last tempo (the
// gallery's own time, so phase-driven pictures glide on), the status says so, and pulses that come
// back carry on from there unless a start, continue or song position says otherwise.
// Pure logic on the times it is given; any byte order is taken without complaint beyond MidiStream's.
#include <cstdint>
#include <optional>

#include "rig/clock_status.h"
#include "rig/pulse_fit.h"

namespace vitrine::rig {

class MidiClock {
 public:
  static constexpr int kPulsesPerQuarter = 24;
  static constexpr size_t kFitPulses = 4 * kPulsesPerQuarter;
  static constexpr double kLostSeconds = 1.0;  // a pulse is 125 ms apart at 20 BPM
  static constexpr double kMinBpm = 10.0, kMaxBpm = 999.0;  // beyond: a tempo nobody plays, not reported

  // 0xF8, 0xFA, 0xFB, 0xFC at `time` (seconds, non-decreasing); other bytes are ignored.
  void realtime(double time, uint8_t status);
  // 0xF2's value: the position in sixteenth notes (0..16383) from which a continue plays.
  void songPosition(int sixteenths);

  std::optional<double> bpm() const;  // none until three pulses; kept while lost
  double jitterMs() const { return fit_.jitter() * 1000.0; }
  // Started or continued, not stopped since; with no start, stop or continue ever seen, any pulse heard.
  bool running() const { return running_ || (!transportSeen_ && heard()); }
  bool heard() const { return fit_.last().has_value(); }  // a pulse has come
  bool locked(double now) const;  // pulses arriving
  // Quarter notes since the song's start at `now`: between pulses, and while lost, it runs on at the
  // fitted tempo from the last pulse; stopped, it holds.
  double beat(double now) const;
  ClockStatus status(double now) const;

 private:
  void pulse(double time);
  PulseFit fit_{kFitPulses};
  int64_t pulses_ = 0;        // the position in pulses at the last pulse
  bool running_ = false;
  bool transportSeen_ = false;  // a start, stop or continue has come
  bool firstPulse_ = false;   // the next pulse is the downbeat at pulses_ (after a start or continue)
  double heldInterval_ = 0.0;  // the last fitted interval, for the flywheel while the window refills
};

}  // namespace vitrine::rig
