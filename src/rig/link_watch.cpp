#include "rig/link_watch.h"

#include <fmt/format.h>

#include <cmath>

namespace vitrine::rig {
namespace {

constexpr Micros kRateWindow{1'000'000};

std::string peersText(size_t peers) { return fmt::format("{} peer{}", peers, peers == 1 ? "" : "s"); }

}  // namespace

std::string linkClockText(const LinkReading& r) {
  return fmt::format("beat {:.4f}, link clock {:.6f} s", r.beat, double(r.hostTime.count()) * 1e-6);
}

void LinkWatch::observe(const LinkReading& r) {
  const std::optional<LinkReading> was = std::exchange(last_, r);
  if (!was) {
    news_.push_back(fmt::format("on, {} beats a bar; {}: own clock at {:.2f} BPM", quantum_,
                                r.peers ? peersText(r.peers) : "no peers yet", r.bpm));
    return;
  }
  if (r.peers != was->peers) {
    if (r.peers == 0) {
      lostAt_ = r.hostTime;
      news_.push_back(fmt::format("every peer left: own clock from here at {:.2f} BPM ({})", r.bpm, linkClockText(r)));
    } else {
      lostAt_.reset();
      news_.push_back(fmt::format("{} ({:.2f} BPM)", peersText(r.peers), r.bpm));
    }
  }
  if (r.playing != was->playing)
    news_.push_back(fmt::format("the transport {} ({})", r.playing ? "plays" : "stops", linkClockText(r)));

  while (!changeTimes_.empty() && r.hostTime - changeTimes_.front() > kRateWindow) changeTimes_.pop_front();
  const bool tempoChanged = r.bpm != was->bpm;
  if (tempoChanged) ++changes_, changeTimes_.push_back(r.hostTime);
  if (changes_ > 0 && (!toldAt_ || r.hostTime - *toldAt_ >= kTempoNewsEvery)) {
    news_.push_back(changes_ == 1 ? fmt::format("tempo {:.2f} BPM ({})", r.bpm, linkClockText(r))
                                  : fmt::format("tempo {:.2f} BPM ({}) after {} changes in {:.1f} s", r.bpm,
                                                linkClockText(r), changes_, double((r.hostTime - *toldAt_).count()) * 1e-6));
    toldAt_ = r.hostTime;
    changes_ = 0;
  }

  // Jitter: how far each reading's beat lands from where the previous reading's beat and tempo put it,
  // in milliseconds, RMS over the last seconds. Readings across a tempo change are left out: the
  // timeline bends there on purpose.
  while (!misses_.empty() && r.hostTime - misses_.front().first > kJitterWindow) misses_.pop_front();
  if (!tempoChanged && r.bpm > 0.0) {
    const double expected = was->beat + double((r.hostTime - was->hostTime).count()) * 1e-6 * r.bpm / 60.0;
    misses_.emplace_back(r.hostTime, (r.beat - expected) * 60'000.0 / r.bpm);
  }
  double sum = 0.0;
  for (const auto& [at, ms] : misses_) sum += ms * ms;
  jitterMs_ = misses_.empty() ? 0.0 : std::sqrt(sum / double(misses_.size()));
}

ClockStatus LinkWatch::status(bool enabled) const {
  ClockStatus status;
  status.name = "link";
  const size_t peers = last_ ? last_->peers : 0;
  status.locked = enabled && peers > 0;
  if (last_) status.bpm = last_->bpm;
  status.jitterMs = jitterMs_;
  if (!enabled) status.note = "off: own clock";
  else if (peers > 0) status.note = peersText(peers);
  else if (lostAt_ && last_)
    status.note = fmt::format("every peer left {:.0f} s ago: own clock", double((last_->hostTime - *lostAt_).count()) * 1e-6);
  else status.note = "no peers: own clock";
  if (changeTimes_.size() >= kFloodChanges)
    status.note += fmt::format(", tempo changing {} times a second", changeTimes_.size());
  return status;
}

}  // namespace vitrine::rig
