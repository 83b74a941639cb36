#pragma once
// A playlist chased by timecode (host/gallery/playlist.h, lines `at HH:MM:SS:FF SCENE [PRESET]`): the
// show controller's MIDI timecode or LTC says where the show is, and the line showing is the last one
// whose frame has come. Time running on into the next line's frame fades it in, starting on that
// frame; any other change (the controller located, backwards or forwards) cuts to the line at once.
//
// Losing the timecode in an installation must not stop the room: the chase free-runs on the
// gallery's own clock from where the timecode was, the lines still starting on their frames, and says
// so; the timecode coming back takes over again (cutting if it disagrees by more than half a second).
// A stopped transport that locates (MIDI timecode's full frame) is followed and parks there. Before any
// timecode it waits on the first line. Pure logic: the gallery gives it the source's
// reading and the seconds between frames.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rig/mtc.h"
#include "rig/timecode.h"

namespace vitrine::host {

class TimecodeChase {
 public:
  // Timecode and the free-running clock disagreeing by more than this is a locate: a cut.
  static constexpr double kJumpSeconds = 0.5;

  // The lines' start labels, in time order (parsePlaylist sees to it).
  explicit TimecodeChase(std::vector<rig::Timecode> starts);

  struct Step {
    std::optional<size_t> cue;  // the line to show from now on
    bool cut = false;           // cut to it (a locate, the first timecode), rather than fade
  };
  // Once a frame: the source's reading (none: nothing heard yet), whether it is locked (running and
  // heard now), and the seconds since the last call.
  Step advance(const std::optional<rig::TimecodePosition>& reading, bool locked, double elapsed);

  size_t current() const { return current_; }
  // The line a position falls in: the last whose frame has come (the first before any has).
  size_t lineAt(double frames, rig::FrameRate rate) const;
  // The frame line `line` starts on at `rate`; a label that rate lacks (frame 27 at 25 fps, a dropped
  // 29.97 label) starts on the next that exists.
  int64_t startFrame(size_t line, rig::FrameRate rate) const;
  // "following 00:01:30:00 (25 fps), line 2 of 5", "timecode lost 3 s ago: free-running at ...",
  // "waiting for timecode on line 1 of 5".
  std::string status() const;
  bool freeRunning() const { return freeRunning_; }

 private:
  std::vector<rig::Timecode> starts_;
  size_t current_ = 0;
  std::optional<double> frames_;  // where the chase is, frames since 00:00:00:00 (fraction included)
  rig::FrameRate rate_ = rig::FrameRate::Fps25;
  bool freeRunning_ = false;
  bool parked_ = false;  // a located reading on a stopped transport: held, not free-run
  std::optional<rig::TimecodePosition> lastReading_;
  double lostFor_ = 0.0;
};

}  // namespace vitrine::host
