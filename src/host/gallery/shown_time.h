#pragma once
// How long the gallery showed frames, for the frame rate it reports when it closes: from the first frame
// shown to now, less the spells spent minimised after it. Counting those made a gallery left minimised
// for a minute report a fraction of the rate it drew at, and scripts/gallery-fps reads that line.
#include <chrono>

namespace vitrine::host {

class ShownTime {
 public:
  using Clock = std::chrono::steady_clock;

  void firstShown(Clock::time_point at) {
    first_ = at;
    shown_ = true;
  }
  // A spell minimised, from `from` to `to`; one before the first frame is no part of the count.
  void hidden(Clock::time_point from, Clock::time_point to) {
    if (shown_) hidden_ += to - from;
  }
  double seconds(Clock::time_point now) const {
    return shown_ ? std::chrono::duration<double>(now - first_ - hidden_).count() : 0.0;
  }

 private:
  Clock::time_point first_{};
  Clock::duration hidden_{};
  bool shown_ = false;
};

}  // namespace vitrine::host
