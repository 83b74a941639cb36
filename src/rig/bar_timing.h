#pragma once
// Bars of a shared beat timeline (Ableton Link's, src/rig/link_clock.h): where a bar begins, how long
// until the next one, and a gate that lets a switch through only as a bar begins. Pure logic on beats
// and microseconds of the host's clock; no Link here, so tests check it without a network.
#include <chrono>
#include <cstdint>
#include <optional>

namespace vitrine::rig {

using Micros = std::chrono::microseconds;

// The bar holding `beat` (bar 0 holds beats 0 up to `quantum`; negative beats are in negative bars).
// `quantum` (beats a bar) must be above 0.
int64_t barOf(double beat, double quantum);
// How far into its bar `beat` is, 0 <= phase < quantum.
double phaseOf(double beat, double quantum);
// The beat on which the next bar after `beat` begins; a beat exactly on a bar's start is that bar's, so
// a switch asked for on the first beat of a bar still waits for the next one (it was asked late).
double nextBarBeat(double beat, double quantum);
// The host time of the next bar's start, seen from `now`, where the timeline is at `beat` and runs at
// `bpm` (above 0) until then.
Micros nextBarTime(Micros now, double beat, double bpm, double quantum);

// Lets a requested switch through on the first observation in a new bar. observe() is called once a
// frame with the timeline's beat; it returns the bar that began since the last call, if one did. A
// timeline that jumps back (a peer joined and the session realigned) starts no bar: the gate waits for
// the next real bar line. Not a beat: NaN or infinities start nothing.
class BarGate {
 public:
  std::optional<int64_t> observe(double beat, double quantum);
  // The beat of the last observation that counted (none before the first): where the frame before a
  // bar line was, to show that a switch came on the bar's first frame.
  std::optional<double> lastBeat() const { return beat_; }

 private:
  std::optional<int64_t> bar_;
  std::optional<double> beat_;
};

}  // namespace vitrine::rig
