#include "host/live_clocks.h"

#include "live/source_bank.h"
#include "rig/ltc_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace vitrine::host {
namespace {

// A timecode as two sources: seconds through the minute and minutes through the hour, each 0..1.
void writeTimecode(live::SourceBank& sources, const std::string& family, const std::optional<rig::TimecodePosition>& at,
                   bool locked) {
  if (!at) return;
  const double seconds = at->seconds();
  sources.set(family + ".seconds", float(std::fmod(seconds, 60.0) / 60.0));
  sources.set(family + ".minutes", float(std::fmod(seconds / 60.0, 60.0) / 60.0));
  sources.set(family + ".locked", locked ? 1.0f : 0.0f);
}

}  // namespace

LiveClocks::LiveClocks() = default;
LiveClocks::~LiveClocks() = default;

void LiveClocks::midiBytes(std::span<const live::MidiInput::TimedByte> bytes) {
  for (const auto& timed : bytes) midi_.feed(timed.time, timed.byte);
}

void LiveClocks::ltcSamples(double sampleRate, std::span<const float> samples) {
  if (!ltc_ || sampleRate != ltcRate_) ltc_ = std::make_unique<rig::LtcReader>(sampleRate), ltcRate_ = sampleRate;
  ltc_->push(samples);
}

void LiveClocks::ltcRestart() {
  if (ltc_) ltc_ = std::make_unique<rig::LtcReader>(ltcRate_);
}

void LiveClocks::write(live::SourceBank& sources, double now) {
  const rig::MidiClock& clock = midi_.clock();
  if (clock.heard()) {
    const double beat = clock.beat(now);
    const auto whole = int64_t(std::floor(beat));
    // A trigger, as audio.beat: 1 for the step in which a new beat begins.
    sources.set("midi.clock.beat", lastBeat_ != INT64_MIN && whole != lastBeat_ ? 1.0f : 0.0f);
    lastBeat_ = whole;
    sources.set("midi.clock.tempo", float(clock.bpm().value_or(0.0) / 240.0));
    sources.set("midi.clock.phase", float(beat - std::floor(beat)));
    sources.set("midi.clock.bar", float(std::fmod(beat, 4.0) / 4.0 + (beat < 0 ? 1.0 : 0.0)));
    sources.set("midi.clock.running", clock.running() ? 1.0f : 0.0f);
  }
  writeTimecode(sources, "mtc", midi_.mtc().position(), midi_.mtc().locked(now));
  if (ltc_) writeTimecode(sources, "ltc", ltc_->position(), ltc_->locked());
  sayChanges(now);
}

std::vector<rig::ClockStatus> LiveClocks::statuses(double now) const {
  std::vector<rig::ClockStatus> clocks;
  if (midi_.clock().heard()) clocks.push_back(midi_.clock().status(now));
  if (midi_.mtc().position() || midi_.mtc().refused() > 0) clocks.push_back(midi_.mtc().status(now));
  if (ltc_ && (ltc_->position() || ltc_->refused() > 0)) clocks.push_back(ltc_->status());
  return clocks;
}

LiveClocks::Timecode LiveClocks::timecode(double now) const {
  if (midi_.mtc().position()) return {midi_.mtc().position(), midi_.mtc().locked(now), "mtc"};
  if (ltc_ && ltc_->position()) return {ltc_->position(), ltc_->locked(), "ltc"};
  return {};
}

// One line when a clock locks or is lost, and when garbage starts coming: never one a frame.
void LiveClocks::sayChanges(double now) {
  for (const rig::ClockStatus& clock : statuses(now)) {
    auto said = std::find_if(said_.begin(), said_.end(), [&](const auto& entry) { return entry.first == clock.name; });
    if (said == said_.end()) said = said_.insert(said_.end(), {clock.name, false});
    if (said->second == clock.locked) continue;
    said->second = clock.locked;
    std::fprintf(stderr, "vitrine: %s: %s%s\n", clock.name.c_str(), clock.locked ? "locked, " : "", clock.note.c_str());
  }
  if (midi_.refused() > troubleSaid_) {
    if (troubleSaid_ == 0)
      std::fprintf(stderr, "vitrine: MIDI clock/timecode: refused %s (further refusals are counted, not said)\n",
                   midi_.trouble().c_str());
    troubleSaid_ = midi_.refused();
  }
}

}  // namespace vitrine::host
