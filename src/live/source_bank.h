#pragma once
// The live sources' values for one simulation step, by name (live/mapping.h lists the families). Inputs
// write what they have once a step; a name nobody wrote reads 0 (a MIDI control never moved, a pad not
// plugged in), except LFOs, which are the simulation time's: lfo.sine.8 is a sine of period 8 s.
#include <map>
#include <string>
#include <string_view>

namespace vitrine::live {

// An LFO's value at simulation time `seconds`, 0..1, starting at 0: sine (raised cosine), triangle,
// saw (rising) or square (1 for the first half). `name` must pass checkSourceName; others read 0.
float lfoValue(std::string_view name, double seconds);

class SourceBank {
 public:
  void setTime(double seconds) { time_ = seconds; }
  double time() const { return time_; }
  // Clamped to 0..1 (NaN reads 0).
  void set(std::string_view name, float value);
  float value(std::string_view name) const;
  // Every value written so far, for the panel's meters and MIDI learn.
  const std::map<std::string, float, std::less<>>& values() const { return values_; }

 private:
  double time_ = 0.0;
  std::map<std::string, float, std::less<>> values_;
};

}  // namespace vitrine::live
