#pragma once
// One MIDI channel voice message with its time: the one shape the modulation layer reads, whether it
// came from a Standard MIDI File (live/smf.h) or from a controller (live/midi_input.h).
#include <cstdint>

namespace vitrine::live {

// A channel voice message (status 0x80..0xEF); system messages are not kept.
struct MidiMessage {
  double time = 0.0;  // seconds: from the file's start (SMF) or arrival (steady clock seconds, live)
  uint8_t status = 0, data1 = 0, data2 = 0;
  int channel() const { return (status & 0x0F) + 1; }  // 1..16 as people count
  uint8_t type() const { return status & 0xF0; }       // 0x90 note on, 0x80 note off, 0xB0 control change, ...
  bool operator==(const MidiMessage&) const = default;
};

// How many data bytes follow a channel voice status: one for program change (0xC0) and channel
// pressure (0xD0), two for the rest. For a status outside 0x80..0xEF, 0.
constexpr int midiDataBytes(uint8_t status) {
  if (status < 0x80 || status >= 0xF0) return 0;
  const uint8_t type = status & 0xF0;
  return type == 0xC0 || type == 0xD0 ? 1 : 2;
}

}  // namespace vitrine::live
