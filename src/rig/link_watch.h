#pragma once
// What the gallery tells of an Ableton Link session (src/rig/link_clock.h), from the readings taken
// once a simulation step: its status for the menu and the remote page (a peer there or not, the tempo,
// the jitter, a note) and lines for the console. Pure logic on readings: tests feed it any timeline.
#include "rig/bar_timing.h"
#include "rig/clock_status.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace vitrine::rig {

// The session as one step sees it.
struct LinkReading {
  Micros hostTime{0};   // the host clock the reading is for (Link's: CLOCK_MONOTONIC_RAW)
  double bpm = 120.0;
  double beat = 0.0;    // the session's beat, counted from its start
  double phase = 0.0;   // 0 <= phase < quantum
  int64_t bar = 0;
  bool playing = false;
  bool beatBegan = false;  // a new beat began since the previous reading
  size_t peers = 0;
};

class LinkWatch {
 public:
  // A tempo changing on this many readings of one second is called a flood in the status.
  static constexpr size_t kFloodChanges = 10;
  static constexpr Micros kJitterWindow{2'000'000};   // the jitter is of the last two seconds' readings
  static constexpr Micros kTempoNewsEvery{1'000'000};  // the console hears of tempo changes once a second at most

  explicit LinkWatch(double quantum) : quantum_(quantum) {}
  void observe(const LinkReading& reading);
  // `enabled`: the gallery is in the session (not switched off).
  ClockStatus status(bool enabled) const;
  // Lines for the console since the last call: peers coming and going, the transport, tempo changes (at
  // most one line a second, counting the changes in between, so a peer flooding changes stays a trickle).
  std::vector<std::string> takeNews() { return std::exchange(news_, {}); }
  void say(std::string line) { news_.push_back(std::move(line)); }

 private:
  double quantum_;
  std::optional<LinkReading> last_;
  std::optional<Micros> lostAt_;        // when the last peer left
  double jitterMs_ = 0.0;
  std::deque<std::pair<Micros, double>> misses_;  // per reading over the last seconds: ms off the straight line
  std::optional<Micros> toldAt_;        // the last line about the tempo
  int changes_ = 0;                     // tempo changes seen since the last line about them
  std::deque<Micros> changeTimes_;      // readings in the last second that saw a new tempo
  std::vector<std::string> news_;
};

// "beat 12.0003, link clock 2345.678901 s": where a console line happened on the session and the host.
std::string linkClockText(const LinkReading& reading);

}  // namespace vitrine::rig
