// Standard MIDI Files (src/live/smf.h): any bytes either parse or are refused with a vitrine::Error
// naming the file and a byte; a parsed sequence keeps its promises (channel messages only, finite
// times in order, none after its end) and plays to the end through SmfPlayer, each message once. A
// sequence written back by writeSmf (when it fits a file) reads back the same within half a tick.
#include "live/smf.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "core/error.h"
#include "support/require.h"

using namespace vitrine;
using vitrine::fuzz::require;

namespace {

void checkSequence(const live::MidiSequence& sequence) {
  double last = 0.0;
  for (const live::MidiMessage& m : sequence.messages) {
    require(std::isfinite(m.time) && m.time >= last, "times are not finite and non-decreasing");
    require(m.status >= 0x80 && m.status < 0xF0, "a kept message is not a channel voice message");
    require(m.data1 < 0x80 && m.data2 < 0x80, "a data byte is over 0x7F");
    last = m.time;
  }
  require(std::isfinite(sequence.seconds) && sequence.seconds >= last, "the sequence ends before its last message");
}

void play(const live::MidiSequence& sequence) {
  live::SmfPlayer player(sequence);
  std::vector<live::MidiMessage> played;
  // A bounded number of steps whatever the length, then one just past the end.
  constexpr int kSteps = 64;
  for (int step = 0; step <= kSteps; ++step) {
    for (const auto& m : player.until(sequence.seconds * step / kSteps)) played.push_back(m);
    require(player.until(sequence.seconds * step / kSteps / 2).empty(), "going back in time returned messages");
  }
  for (const auto& m : player.until(std::nextafter(sequence.seconds, std::numeric_limits<double>::infinity())))
    played.push_back(m);
  require(player.finished(), "the player is not finished past the sequence's end");
  require(played == sequence.messages, "the player did not return every message once, in order");
}

void roundTrip(const live::MidiSequence& sequence) {
  constexpr int kPpq = 480;
  std::vector<uint8_t> file;
  try {
    file = live::writeSmf(sequence.messages, kPpq);
  } catch (const Error&) {
    return;  // a gap longer than one delta time holds: writeSmf says so rather than writing it wrong
  }
  const live::MidiSequence back = live::parseSmf(file, "written.mid");
  require(back.messages.size() == sequence.messages.size(), "writeSmf lost or added messages");
  const double halfTick = 0.5 / kPpq / 2.0;  // 120 BPM: two quarters a second
  for (size_t i = 0; i < back.messages.size(); ++i) {
    const live::MidiMessage& a = sequence.messages[i];
    const live::MidiMessage& b = back.messages[i];
    require(a.status == b.status && a.data1 == b.data1 && (live::midiDataBytes(a.status) == 1 || a.data2 == b.data2),
            "writeSmf changed a message");
    require(std::abs(a.time - b.time) <= halfTick + 1e-9 * a.time, "writeSmf moved a message by over half a tick");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  live::MidiSequence sequence;
  try {
    sequence = live::parseSmf(std::span(data, size), "fuzz.mid");
  } catch (const Error& error) {
    require(std::string_view(error.what()).starts_with("fuzz.mid: byte "), "an error does not name the file and byte");
    return 0;
  }
  checkSequence(sequence);
  play(sequence);
  roundTrip(sequence);
  return 0;
}
