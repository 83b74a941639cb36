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
namespace {

constexpr Micros kJitterWindow{2'000'000};   // the jitter is of the last two seconds' readings
constexpr Micros kTempoNewsEvery{1'000'000};  // the console hears of tempo changes once a second at most
constexpr Micros kRateWindow{1'000'000};

std::string peersText(size_t peers) { return fmt::format("{} peer{}", peers, peers == 1 ? "" : "s"); }
std::string clockText(const LinkReading& r) {
  return fmt::format("beat {:.4f}, link clock {:.6f} s", r.beat, double(r.hostTime.count()) * 1e-6);
}

}  // namespace

LinkClock::LinkClock(LinkSettings settings)
    : settings_(std::move(settings)),
      link_(std::make_unique<ableton::Link>(std::clamp(settings_.leadTempo.value_or(120.0), kMinBpm, kMaxBpm))) {
  link_->enableStartStopSync(true);
  link_->enable(true);
}

LinkClock::~LinkClock() = default;

LinkReading LinkClock::read() {
  const bool joined = link_->numPeers() > 0;
  if (settings_.leadTempo && joined && !joined_) {  // each session joined from alone hears the lead tempo
    setTempo(*settings_.leadTempo);
    news_.push_back(fmt::format("leading the session's tempo: {:.2f} BPM (link clock {:.6f} s)", *settings_.leadTempo,
                                double(link_->clock().micros().count()) * 1e-6));
  }
  joined_ = joined;
  LinkReading r = look();
  r.beatBegan = last_ && std::floor(r.beat) > std::floor(last_->beat);
  watch(r);
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

void LinkClock::watch(const LinkReading& r) {
  if (!last_) {
    news_.push_back(fmt::format("on, {} beats a bar; {}: own clock at {:.2f} BPM", settings_.quantum,
                                r.peers ? peersText(r.peers) : "no peers yet", r.bpm));
    return;
  }
  const LinkReading& was = *last_;
  if (r.peers != was.peers) {
    if (r.peers == 0) {
      lostAt_ = r.hostTime;
      news_.push_back(fmt::format("every peer left: own clock from here at {:.2f} BPM ({})", r.bpm, clockText(r)));
    } else {
      lostAt_.reset();
      news_.push_back(fmt::format("{} ({:.2f} BPM)", peersText(r.peers), r.bpm));
    }
  }
  if (r.playing != was.playing) news_.push_back(fmt::format("the transport {} ({})", r.playing ? "plays" : "stops", clockText(r)));

  while (!changeTimes_.empty() && r.hostTime - changeTimes_.front() > kRateWindow) changeTimes_.pop_front();
  const bool tempoChanged = r.bpm != was.bpm;
  if (tempoChanged) ++changes_, changeTimes_.push_back(r.hostTime);
  if (changes_ > 0 && r.hostTime - toldAt_ >= kTempoNewsEvery) {
    news_.push_back(changes_ == 1 ? fmt::format("tempo {:.2f} BPM ({})", r.bpm, clockText(r))
                                  : fmt::format("tempo {:.2f} BPM ({}) after {} changes in {:.1f} s", r.bpm, clockText(r),
                                                changes_, double((r.hostTime - toldAt_).count()) * 1e-6));
    toldAt_ = r.hostTime;
    changes_ = 0;
  }

  // Jitter: how far each reading's beat lands from where the previous reading's beat and tempo put it,
  // in milliseconds, RMS over the last seconds. Readings across a tempo change are left out: the
  // timeline bends there on purpose.
  while (!misses_.empty() && r.hostTime - misses_.front().first > kJitterWindow) misses_.pop_front();
  if (!tempoChanged && r.bpm > 0.0) {
    const double expected = was.beat + double((r.hostTime - was.hostTime).count()) * 1e-6 * r.bpm / 60.0;
    misses_.emplace_back(r.hostTime, (r.beat - expected) * 60'000.0 / r.bpm);
  }
  double sum = 0.0;
  for (const auto& [at, ms] : misses_) sum += ms * ms;
  jitterMs_ = misses_.empty() ? 0.0 : std::sqrt(sum / double(misses_.size()));
}

void LinkClock::setTempo(double bpm) {
  if (!std::isfinite(bpm)) return;
  auto state = link_->captureAppSessionState();
  state.setTempo(std::clamp(bpm, kMinBpm, kMaxBpm), link_->clock().micros());
  link_->commitAppSessionState(state);
}

void LinkClock::setPlaying(bool playing) {
  auto state = link_->captureAppSessionState();
  state.setIsPlaying(playing, link_->clock().micros());
  link_->commitAppSessionState(state);
}

void LinkClock::setEnabled(bool on) {
  if (on != link_->isEnabled()) news_.push_back(on ? "joining the session again" : "off: own clock");
  link_->enable(on);
}

bool LinkClock::enabled() const { return link_->isEnabled(); }

ClockStatus LinkClock::status() const {
  ClockStatus status;
  status.name = "link";
  const size_t peers = last_ ? last_->peers : 0;
  status.locked = peers > 0;
  if (last_) status.bpm = last_->bpm;
  status.jitterMs = jitterMs_;
  if (!link_->isEnabled()) status.note = "off: own clock";
  else if (peers > 0) status.note = peersText(peers);
  else if (lostAt_ && last_)
    status.note = fmt::format("every peer left {:.0f} s ago: own clock", double((last_->hostTime - *lostAt_).count()) * 1e-6);
  else status.note = "no peers: own clock";
  if (changeTimes_.size() >= kFloodChanges)
    status.note += fmt::format(", tempo changing {} times a second", changeTimes_.size());
  return status;
}

std::vector<std::string> LinkClock::takeNews() { return std::exchange(news_, {}); }

}  // namespace vitrine::rig
