#pragma once
// A straight line through the arrival times of a clock's last few evenly spaced events (MIDI clock
// pulses, MTC quarter frames): its slope is the source's interval, smoothed over the window, and the
// spread of the arrivals around it is the source's jitter. Least squares, so one late pulse moves the
// interval by a fraction of its lateness over the window's length.
#include <cmath>
#include <cstddef>
#include <deque>
#include <optional>

namespace vitrine::rig {

class PulseFit {
 public:
  explicit PulseFit(size_t window) : window_(window < 3 ? 3 : window) {}

  void add(double time) {
    times_.push_back(time);
    if (times_.size() > window_) times_.pop_front();
  }
  // Keeps only the newest `keep` arrivals (the source changed its pace).
  void keepNewest(size_t keep) {
    while (times_.size() > keep) times_.pop_front();
  }
  // How many of the newest gaps run nearer `pace` than `old` (seconds), counted back until one does not.
  size_t newestNearer(double pace, double old) const {
    size_t n = 0;
    for (size_t i = times_.size(); i-- > 1; ++n) {
      const double gap = times_[i] - times_[i - 1];
      if (std::abs(gap - pace) >= std::abs(gap - old)) break;
    }
    return n;
  }
  // Drops the oldest arrival while the gap after it is over `tolerance` seconds off the fitted interval.
  void dropLeadingGapsOff(double tolerance) {
    while (times_.size() > 4) {
      const auto line = fit();
      if (!line || std::abs((times_[1] - times_[0]) - line->slope) <= tolerance) return;
      times_.pop_front();
    }
  }
  void clear() { times_.clear(); }
  size_t size() const { return times_.size(); }
  std::optional<double> last() const { return times_.empty() ? std::nullopt : std::optional(times_.back()); }

  // Seconds between events, fitted; none before three arrivals.
  std::optional<double> interval() const {
    const auto line = fit();
    return line ? std::optional(line->slope) : std::nullopt;
  }
  // The root mean square of the arrivals' distances from the line, seconds; 0 before three arrivals.
  double jitter() const {
    const auto line = fit();
    if (!line) return 0.0;
    double sum = 0.0;
    for (size_t i = 0; i < times_.size(); ++i) {
      const double miss = (times_[i] - times_.front()) - (line->offset + line->slope * double(i));
      sum += miss * miss;
    }
    return std::sqrt(sum / double(times_.size()));
  }
  // The mean interval of the newest `n` gaps (n + 1 arrivals), unfitted; none with fewer arrivals.
  std::optional<double> recentInterval(size_t n) const {
    if (n == 0 || times_.size() < n + 1) return std::nullopt;
    return (times_.back() - times_[times_.size() - 1 - n]) / double(n);
  }

 private:
  struct Line {
    double offset, slope;  // time - times_.front() = offset + slope x index
  };
  std::optional<Line> fit() const {
    const size_t n = times_.size();
    if (n < 3) return std::nullopt;
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (size_t i = 0; i < n; ++i) {
      const double x = double(i), y = times_[i] - times_.front();
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double slope = (double(n) * sxy - sx * sy) / (double(n) * sxx - sx * sx);
    return Line{(sy - slope * sx) / double(n), slope};
  }
  size_t window_;
  std::deque<double> times_;
};

}  // namespace vitrine::rig
