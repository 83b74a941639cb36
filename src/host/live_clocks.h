#pragma once
// The show's clocks as live input (docs/LIVE.md, docs/RIG.md): MIDI clock and MIDI timecode from the
// MIDI ports' system messages (rig/midi_timing.h), LTC from the sound input (rig/ltc_reader.h), as
// sources for the modulation layer, as rig::ClockStatus for the menu and the remote page, and as the
// timecode a chased playlist follows. A clock that locks or is lost says so once on the console.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "live/midi_input.h"
#include "rig/clock_status.h"
#include "rig/midi_timing.h"
#include "rig/mtc.h"

namespace vitrine::live {
class SourceBank;
}
namespace vitrine::rig {
class LtcReader;
}

namespace vitrine::host {

class LiveClocks {
 public:
  LiveClocks();
  ~LiveClocks();

  // System message bytes from the MIDI ports, timed in MidiInput::clockSeconds().
  void midiBytes(std::span<const live::MidiInput::TimedByte> bytes);
  // Mono sound that follows what was given before, at `sampleRate` (a new rate starts afresh).
  void ltcSamples(double sampleRate, std::span<const float> samples);
  // The sound jumped (a looped file started again, a seek): LTC is read afresh from here.
  void ltcRestart();

  // Writes midi.clock.*, mtc.* and ltc.* for the clocks heard; `now` in MidiInput::clockSeconds().
  void write(live::SourceBank& sources, double now);
  // The clocks heard so far (none: nothing heard, nothing to show).
  std::vector<rig::ClockStatus> statuses(double now) const;

  // The timecode a chased playlist follows: MIDI timecode once heard, else LTC.
  struct Timecode {
    std::optional<rig::TimecodePosition> position;
    bool locked = false;
    std::string source;  // "mtc", "ltc", or empty: none heard
  };
  Timecode timecode(double now) const;

 private:
  void sayChanges(double now);
  rig::MidiTiming midi_;
  std::unique_ptr<rig::LtcReader> ltc_;
  double ltcRate_ = 0.0;
  int64_t lastBeat_ = INT64_MIN;
  std::vector<std::pair<std::string, bool>> said_;  // each clock's lock as last said
  uint64_t troubleSaid_ = 0;                       // refusals already said
};

}  // namespace vitrine::host
