#include "rig/bar_timing.h"

#include <cmath>

namespace vitrine::rig {

int64_t barOf(double beat, double quantum) { return int64_t(std::floor(beat / quantum)); }

double phaseOf(double beat, double quantum) {
  const double phase = beat - std::floor(beat / quantum) * quantum;
  return phase >= quantum ? 0.0 : phase;  // rounding can land on quantum itself
}

double nextBarBeat(double beat, double quantum) { return double(barOf(beat, quantum) + 1) * quantum; }

Micros nextBarTime(Micros now, double beat, double bpm, double quantum) {
  const double seconds = (nextBarBeat(beat, quantum) - beat) * 60.0 / bpm;
  return now + Micros(int64_t(std::llround(seconds * 1e6)));
}

std::optional<int64_t> BarGate::observe(double beat, double quantum) {
  if (!std::isfinite(beat) || !(quantum > 0.0)) return std::nullopt;
  const int64_t bar = barOf(beat, quantum);
  const std::optional<int64_t> was = bar_;
  bar_ = bar;
  beat_ = beat;
  if (!was || bar <= *was) return std::nullopt;  // the first look, the same bar, or a jump back
  return bar;
}

}  // namespace vitrine::rig
