#pragma once
// The show's clocks that come over MIDI, from one timed byte stream: MIDI clock (rig/midi_clock.h) and
// MIDI timecode (rig/mtc.h), cut apart by rig/midi_stream.h. What a MIDI port delivers and what a test
// writes go through the same feed(), so tests give exact times. Never throws; garbage is counted and
// the last trouble kept as one line (trouble()).
#include <cstdint>
#include <span>
#include <string>

#include "rig/midi_clock.h"
#include "rig/midi_stream.h"
#include "rig/mtc.h"

namespace vitrine::rig {

class MidiTiming : private MidiStreamHandler {
 public:
  void feed(double time, std::span<const uint8_t> bytes);
  void feed(double time, uint8_t byte) { feed(time, std::span<const uint8_t>(&byte, 1)); }

  const MidiClock& clock() const { return clock_; }
  const Mtc& mtc() const { return mtc_; }
  bool heard() const { return heard_; }  // any clock or timecode message has come
  // Bytes and messages refused, the stream's and the timecode's together, and the last reason.
  uint64_t refused() const { return stream_.dropped() + mtc_.refused(); }
  std::string trouble() const;

 private:
  void realtime(double time, uint8_t status) override;
  void common(double time, uint8_t status, std::span<const uint8_t> data) override;
  void sysex(double time, std::span<const uint8_t> body) override;
  MidiStream stream_;
  MidiClock clock_;
  Mtc mtc_;
  bool heard_ = false;
  bool mtcLast_ = false;  // the last trouble was the timecode's
};

}  // namespace vitrine::rig
