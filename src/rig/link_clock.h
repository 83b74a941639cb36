#pragma once
// Ableton Link (docs/RIG.md): the gallery joins the tempo session of the machines on its network (a
// DJ's software, other visuals) and reads, once a simulation step, the session's tempo, beat, phase
// within the bar (the quantum: beats a bar, the user's), bar and whether the transport plays (start/stop
// sync on). It can lead: propose a tempo when it joins, or set one later.
//
// Nothing here waits on the network: Link's own threads talk to the peers, and a read copies the
// session's timeline under Link's lock, which its thread holds only to copy a state. Alone (no peers yet, or every peer gone) the timeline simply runs
// on at its last tempo from the host's clock: beat and phase go on without a jump, and status() says
// the gallery keeps its own time.
#include "rig/clock_status.h"
#include "rig/link_watch.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ableton {
class Link;
}

namespace vitrine::rig {

struct LinkSettings {
  double quantum = 4.0;             // --link-quantum: beats a bar
  std::optional<double> leadTempo;  // --link-tempo: starts the gallery's session, proposed to each one it joins
};

class LinkClock {
 public:
  static constexpr double kMinBpm = 20.0, kMaxBpm = 999.0;        // Link's own tempo range
  static constexpr double kMinQuantum = 1.0, kMaxQuantum = 64.0;  // beats a bar the flags accept
  explicit LinkClock(LinkSettings settings);
  ~LinkClock();
  LinkClock(const LinkClock&) = delete;
  LinkClock& operator=(const LinkClock&) = delete;

  // Once a simulation step: the session now. Also keeps the status and the console's news.
  LinkReading read();
  // The session now, changing nothing (beatBegan is false): for a look between steps.
  LinkReading look() const;
  double quantum() const { return settings_.quantum; }
  // The gallery leads: the session's tempo from now on (clamped to Link's range), or its transport.
  void setTempo(double bpm);
  void setPlaying(bool playing);
  // Leaves the session (the timeline runs on alone, as when every peer left) or joins it again.
  void setEnabled(bool on);
  bool enabled() const;

  // Whether a peer is there, the tempo, the jitter and a note (LinkWatch), and the console's lines.
  ClockStatus status() const;
  std::vector<std::string> takeNews();

 private:
  LinkSettings settings_;
  LinkWatch watch_;
  std::unique_ptr<ableton::Link> link_;
  std::optional<LinkReading> last_;
  bool joined_ = false;  // a peer was there at the last reading
};

}  // namespace vitrine::rig
