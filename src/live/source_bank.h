#pragma once
// The live sources' values for one simulation step, by name (live/mapping.h lists the families). Inputs
// write what they have once a step; a name nobody wrote reads 0 (a MIDI control never moved, a pad not
// plugged in), except LFOs, which are the simulation time's: lfo.sine.8 is a sine of period 8 s.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace vitrine::live {

// An LFO's value at simulation time `seconds`, 0..1, starting at 0: sine (raised cosine), triangle,
// saw (rising) or square (1 for the first half). `name` must pass checkSourceName; others read 0.
float lfoValue(std::string_view name, double seconds);

// Far more than any rig: 128 MIDI controls on 16 channels is 2,048; a few pads and OSC faders add tens.
inline constexpr size_t kMaxSourceNames = 4096;

class SourceBank {
 public:
  void setTime(double seconds) { time_ = seconds; }
  double time() const { return time_; }
  // Clamped to 0..1 (NaN reads 0). A new name beyond kMaxSourceNames takes the place of the name
  // written longest ago that no mapping has read (of any name written longest ago if all were read):
  // a client sending /vitrine/mod/<a new name> in a loop cannot grow memory, nor push out a mapped one.
  void set(std::string_view name, float value);
  float value(std::string_view name) const;
  // Every value written so far (at most kMaxSourceNames), for the panel's meters and MIDI learn.
  const std::map<std::string, float, std::less<>>& values() const { return values_; }

 private:
  struct Use {
    uint64_t written = 0;  // the serial of the last write
    bool read = false;     // a mapping has read it
  };
  void forgetOne();

  double time_ = 0.0;
  uint64_t writes_ = 0;
  std::map<std::string, float, std::less<>> values_;
  mutable std::map<std::string, Use, std::less<>> uses_;
  // Names by the serial of their last write, oldest first: those never read, and those read.
  mutable std::map<uint64_t, std::string> unread_, read_;
};

}  // namespace vitrine::live
