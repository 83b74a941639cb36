#pragma once
// Kiosk mode's schedule (--kiosk): each scene shows for the dwell time, then the next one fades in
// over a couple of seconds while both run. A person touching anything holds the current scene (a fade
// under way completes at once); cycling resumes once nobody has touched anything for the idle time.
// A scene that fails is skipped. Pure logic in seconds: the timetable (host/gallery/kiosk_timetable.h)
// asks it what to do.
//
// What it cycles through are entries: the registry's scenes, each for the same dwell, or the lines of a
// playlist (--playlist, host/gallery/playlist.h), each with its own dwell; the timetable knows which
// scene and preset an entry shows.
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <optional>
#include <vector>

namespace vitrine::host {

struct KioskTiming {
  double dwell = 45.0;  // --dwell: seconds each scene shows
  double fade = 2.0;    // seconds of cross-fade, both scenes running
  double idle = 30.0;   // seconds without input before cycling resumes
};

class KioskSchedule {
 public:
  // `entries` each shown for timing.dwell.
  KioskSchedule(size_t entries, size_t first, KioskTiming timing);
  // One entry per dwell (seconds, above 0), each shown for its own; timing.dwell is not used.
  KioskSchedule(std::vector<double> dwells, size_t first, KioskTiming timing);

  struct Plan {
    std::optional<size_t> begin;  // start this scene as the incoming one (a fade begins)
    std::optional<float> fade;    // during a fade: how far in, 0..1 (the incoming scene's weight)
    bool finish = false;          // the fade is over: the incoming scene is now the current one
  };
  // After `elapsed` more seconds; `touched`: a person used a key, the mouse or a remote this frame.
  // `mayBegin` false holds a fade that is due until a call where it is true (a bar line of Link's).
  Plan advance(double elapsed, bool touched, bool mayBegin = true);
  // The entry at `index` failed (to start, or while running): it is skipped from now on, until every
  // scene has failed, when all are tried again. A failed incoming scene ends its fade.
  void failed(size_t index);
  size_t current() const { return current_; }
  std::optional<size_t> incoming() const { return incoming_; }
  // Someone chose an entry directly (a number key, a phone): it becomes current with no fade.
  void jumpTo(size_t index);
  // Another clock says `index` starts now (a chased playlist's line, its frame come): the next
  // advance() begins its fade, ending a fade under way first, whatever the dwell or a person's touch.
  void cue(size_t index) {
    if (index < failed_.size()) cued_ = index;
  }

 private:
  size_t nextAfter(size_t index) const;
  KioskTiming timing_;
  std::vector<double> dwells_;  // per entry
  std::vector<bool> failed_;
  size_t current_;
  std::optional<size_t> incoming_;
  std::optional<size_t> cued_;
  double shown_ = 0.0;          // seconds the current scene has shown without being held
  double fading_ = 0.0;         // seconds into the fade
  double sinceTouch_ = 1e300;   // seconds since the last touch
};

// The pause before the kiosk starts a fresh gallery after one failed (a lost device, memory running
// out): 1 s, doubling while the failures repeat, at most 60 s; a gallery that ran for kSettled first
// was healthy, so its failure starts again from 1 s (a sixth lost device days after the fifth does
// not leave the room dark for a minute).
class KioskRestartPause {
 public:
  static constexpr std::chrono::seconds kFirst{1}, kLongest{60}, kSettled{600};
  std::chrono::seconds after(std::chrono::seconds ranFor) {
    if (ranFor >= kSettled) next_ = kFirst;
    const std::chrono::seconds pause = next_;
    next_ = std::min(next_ * 2, kLongest);
    return pause;
  }

 private:
  std::chrono::seconds next_ = kFirst;
};

}  // namespace vitrine::host
