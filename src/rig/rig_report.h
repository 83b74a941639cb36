#pragma once
// The rig at a glance, for the menu, the remote page and the console: one line for each clock the
// gallery follows and each output it publishes beyond its windows, and whether that part is well. Pure
// text from the parts' own reports (rig::ClockStatus, an output's Health), so every place shows the
// same words.
#include "rig/clock_status.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vitrine::rig {

struct RigLine {
  std::string name;  // "link", "pipewire obs", "stream srt://..."
  bool ok = true;    // locked, or taking frames without dropping many
  std::string text;  // "locked 128.0 BPM, 2 peers, jitter 0.4 ms"
  bool operator==(const RigLine&) const = default;
};

// What an output that is not a window reports (host/present/output.h's Health, without the host).
struct OutputReport {
  std::string kind;  // "pipewire", "stream"
  std::string name;
  std::string line;
  uint64_t frames = 0;
  uint64_t dropped = 0;
  bool connected = true;
};

RigLine describeClock(const ClockStatus& clock);
RigLine describeOutput(const OutputReport& output);
// "01:02:03:04" for whole frames of a clock whose `fps` is 24, 25, 29.97 or 30 (drop-frame shown with
// ';' before the frames, as SMPTE writes it).
std::string formatTimecode(double seconds, double fps);

}  // namespace vitrine::rig
