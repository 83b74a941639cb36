#pragma once
// What one of the show's clocks (Ableton Link, MIDI clock, MIDI timecode, LTC) says about itself, for the
// menu, the remote page and the console: whether it is locked, its tempo or its time, and how steady it
// is. Each clock fills one of these once a frame; a clock that is lost says so here while the gallery
// glides back to its own time.
#include <optional>
#include <string>

namespace vitrine::rig {

struct ClockStatus {
  std::string name;                  // "link", "midi clock", "mtc", "ltc"
  bool locked = false;               // following the source now
  std::optional<double> bpm;         // tempo, for the clocks that keep one
  std::optional<double> seconds;     // timecode as seconds since 00:00:00:00, for those that keep one
  std::string timecode;              // "HH:MM:SS:FF" where the clock is a timecode, else empty
  double jitterMs = 0.0;             // spread of the source's arrivals around the fitted clock
  std::string note;                  // one line: "2 peers", "lost 3 s ago: own clock", ...
};

}  // namespace vitrine::rig
