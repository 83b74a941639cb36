// MIDI clock and MIDI timecode from a raw byte stream (src/rig/midi_timing.h): any bytes at any pace
// are taken without a crash, and what the clocks then say keeps its promises: a tempo only within
// MidiClock's range, a finite beat, a timecode position inside one day with a fraction in 0..1, and
// statuses and troubles of one short line. The input is pairs: a gap (in half milliseconds) before a
// byte, then the byte.
#include "rig/midi_timing.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "support/require.h"

using namespace vitrine;
using vitrine::fuzz::require;

namespace {

void requireLine(const std::string& text, const char* promise) {
  require(text.size() < 400 && text.find('\n') == std::string::npos, promise);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  rig::MidiTiming timing;
  double time = 0.0;
  for (size_t i = 0; i + 1 < size; i += 2) {
    time += data[i] * 0.0005;
    timing.feed(time, data[i + 1]);
  }
  const rig::MidiClock& clock = timing.clock();
  if (const auto bpm = clock.bpm()) require(*bpm >= rig::MidiClock::kMinBpm && *bpm <= rig::MidiClock::kMaxBpm, "a tempo out of range");
  for (const double later : {0.0, 0.01, 2.0, 3600.0}) {
    require(std::isfinite(clock.beat(time + later)), "the beat is not finite");
    requireLine(clock.status(time + later).note, "the clock's note is not one short line");
    requireLine(timing.mtc().status(time + later).note, "the timecode's note is not one short line");
  }
  require(std::isfinite(clock.jitterMs()) && clock.jitterMs() >= 0.0, "the clock's jitter is not a distance");
  if (const auto at = timing.mtc().position()) {
    require(at->frames >= 0 && at->frames < rig::framesPerDay(at->rate), "a position outside the day");
    require(at->fraction >= 0.0 && at->fraction < 1.0, "a fraction of a frame outside 0..1");
    require(rig::frameCount(at->label(), at->rate) == at->frames, "a position's label is not its frame");
  }
  requireLine(timing.trouble(), "the trouble is not one short line");
  return 0;
}
