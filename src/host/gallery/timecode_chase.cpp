#include "host/gallery/timecode_chase.h"

#include <fmt/format.h>

#include <cmath>
#include <utility>

namespace vitrine::host {

TimecodeChase::TimecodeChase(std::vector<rig::Timecode> starts) : starts_(std::move(starts)) {}

int64_t TimecodeChase::startFrame(size_t line, rig::FrameRate rate) const {
  rig::Timecode label = starts_[line];
  if (const auto count = rig::frameCount(label, rate)) return *count;
  const int fps = rig::labelFps(rate);
  if (label.frames >= fps) {  // past the rate's last frame of that second: the next second's first
    label.frames = 0;
    return rig::frameCount(label, rate).value_or(0) + fps;
  }
  label.frames = 2;  // a dropped 29.97 label: the minute's first label
  return rig::frameCount(label, rate).value_or(0);
}

size_t TimecodeChase::lineAt(double frames, rig::FrameRate rate) const {
  size_t line = 0;
  for (size_t i = 1; i < starts_.size(); ++i)
    if (frames + 1e-6 >= double(startFrame(i, rate))) line = i;
  return line;
}

TimecodeChase::Step TimecodeChase::advance(const std::optional<rig::TimecodePosition>& reading, bool locked,
                                           double elapsed) {
  if (!std::isfinite(elapsed) || elapsed < 0.0) elapsed = 0.0;
  Step step;
  bool jumped = false;
  // A reading that moved while not locked is a locate on a stopped transport (MIDI timecode's full
  // frame): followed, and held there rather than free-run.
  const bool located = reading && !locked && lastReading_ &&
                       (reading->frames != lastReading_->frames || reading->rate != lastReading_->rate);
  if (reading && (locked || located || (!frames_ && !lastReading_))) {
    const double heard = double(reading->frames) + reading->fraction;
    if (frames_) {
      const double ran = *frames_ + (freeRunning_ ? elapsed * rig::realFps(rate_) : 0.0);
      jumped = reading->rate != rate_ || std::abs(heard - ran) > kJumpSeconds * rig::realFps(reading->rate) +
                                                                      elapsed * rig::realFps(reading->rate);
    } else {
      jumped = true;  // the first timecode: straight to its line
    }
    frames_ = heard, rate_ = reading->rate, freeRunning_ = false, lostFor_ = 0.0;
    parked_ = !locked;
  } else if (frames_ && !parked_) {
    // Lost (or stopped without a word): the gallery's own clock carries the show on.
    freeRunning_ = true;
    lostFor_ += elapsed;
    *frames_ += elapsed * rig::realFps(rate_);
  }
  lastReading_ = reading;
  if (!frames_) return step;
  const size_t line = lineAt(*frames_, rate_);
  if (line != current_) {  // a locate within the line showing changes nothing on the screen
    step.cue = line;
    step.cut = jumped || line != current_ + 1;
    current_ = line;
  }
  return step;
}

std::string TimecodeChase::status() const {
  const std::string line = fmt::format("line {} of {}", current_ + 1, starts_.size());
  if (!frames_) return "waiting for timecode on " + line;
  const std::string at = rig::formatTimecode(rig::labelOf(int64_t(std::floor(*frames_)), rate_));
  if (parked_) return fmt::format("parked at {} ({} fps), {}", at, rig::rateName(rate_), line);
  if (freeRunning_)
    return fmt::format("timecode lost {:.0f} s ago: free-running at {} ({} fps), {}", lostFor_, at, rig::rateName(rate_), line);
  return fmt::format("following {} ({} fps), {}", at, rig::rateName(rate_), line);
}

}  // namespace vitrine::host
