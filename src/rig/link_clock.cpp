#include "rig/link_clock.h"

// Link and the asio it brings compile with warnings this project's flags make errors; they are theirs.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <ableton/Link.hpp>
#pragma GCC diagnostic pop

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace vitrine::rig {

LinkClock::LinkClock(LinkSettings settings)
    : settings_(std::move(settings)),
      watch_(settings_.quantum),
      link_(std::make_unique<ableton::Link>(std::clamp(settings_.leadTempo.value_or(120.0), kMinBpm, kMaxBpm))) {
  link_->enableStartStopSync(true);
  link_->enable(true);
}

LinkClock::~LinkClock() = default;

LinkReading LinkClock::read() {
  const bool joined = link_->numPeers() > 0;
  if (settings_.leadTempo && joined && !joined_) {  // each session joined from alone hears the lead tempo
    setTempo(*settings_.leadTempo);
    watch_.say(fmt::format("leading the session's tempo: {:.2f} BPM (link clock {:.6f} s)", *settings_.leadTempo,
                           double(link_->clock().micros().count()) * 1e-6));
  }
  joined_ = joined;
  LinkReading r = look();
  r.beatBegan = last_ && std::floor(r.beat) > std::floor(last_->beat);
  watch_.observe(r);
  last_ = r;
  return r;
}

LinkReading LinkClock::look() const {
  LinkReading r;
  r.peers = link_->numPeers();
  r.hostTime = link_->clock().micros();
  // The application's capture: Link's lock, held by its own thread only to copy a state, never over
  // the network. (The audio thread's lock-free capture sees the network's changes up to half a second
  // late: measured 330 and 560 ms from a peer's tempo change, against 50 ms here.)
  const auto state = link_->captureAppSessionState();
  const double q = settings_.quantum;
  r.bpm = state.tempo();
  r.beat = state.beatAtTime(r.hostTime, q);
  r.phase = phaseOf(r.beat, q);
  r.bar = barOf(r.beat, q);
  r.playing = state.isPlaying();
  return r;
}

void LinkClock::setTempo(double bpm) {
  if (!std::isfinite(bpm)) return;
  settings_.leadTempo = std::clamp(bpm, kMinBpm, kMaxBpm);  // and to each session joined from here on
  auto state = link_->captureAppSessionState();
  state.setTempo(*settings_.leadTempo, link_->clock().micros());
  link_->commitAppSessionState(state);
}

void LinkClock::setPlaying(bool playing) {
  auto state = link_->captureAppSessionState();
  state.setIsPlaying(playing, link_->clock().micros());
  link_->commitAppSessionState(state);
}

void LinkClock::setEnabled(bool on) {
  if (on != link_->isEnabled()) watch_.say(on ? "joining the session again" : "off: own clock");
  link_->enable(on);
}

bool LinkClock::enabled() const { return link_->isEnabled(); }

ClockStatus LinkClock::status() const { return watch_.status(link_->isEnabled()); }

std::vector<std::string> LinkClock::takeNews() { return watch_.takeNews(); }

}  // namespace vitrine::rig
