#include "rig/rig_report.h"

#include <fmt/format.h>

#include <cmath>

namespace vitrine::rig {

RigLine describeClock(const ClockStatus& clock) {
  std::string text = clock.locked ? "locked" : "not locked";
  if (clock.bpm) text += fmt::format(" {:.1f} BPM", *clock.bpm);
  if (!clock.timecode.empty()) text += " " + clock.timecode;
  if (clock.locked && clock.jitterMs > 0.0) text += fmt::format(", jitter {:.2f} ms", clock.jitterMs);
  if (!clock.note.empty()) text += ", " + clock.note;
  return {clock.name, clock.locked, std::move(text)};
}

RigLine describeOutput(const OutputReport& output) {
  std::string text = output.line.empty() ? (output.connected ? "taking frames" : "nobody taking frames") : output.line;
  text += fmt::format(", {} frames", output.frames);
  if (output.dropped > 0) {
    const double share = 100.0 * double(output.dropped) / double(output.frames + output.dropped);
    text += fmt::format(", {} dropped ({:.1f} %)", output.dropped, share);
  }
  // Well while someone takes the frames and at most one in twenty is dropped: a consumer at half the
  // gallery's rate drops every other frame, which is its choice, but says so in amber.
  const bool ok = output.connected && output.dropped * 20 <= output.frames + output.dropped;
  // "pipewire stage"; an output named after its kind ("stream") is not named twice.
  std::string name = output.name == output.kind ? output.kind : output.kind + " " + output.name;
  return {std::move(name), ok, std::move(text)};
}

std::string formatTimecode(double seconds, double fps) {
  if (!std::isfinite(seconds) || seconds < 0.0) seconds = 0.0;
  const bool drop = std::abs(fps - 29.97) < 0.01;
  const int nominal = int(std::lround(fps));
  int64_t frame = int64_t(std::floor(seconds * fps + 1e-6));
  if (drop) {
    // SMPTE drop-frame: frame numbers 0 and 1 are skipped at the start of every minute but each tenth,
    // so the label runs with the wall clock at 30000/1001 frames a second.
    const int64_t perTen = 17982, perMinute = 1798;
    const int64_t tens = frame / perTen, rest = frame % perTen;
    frame += 18 * tens + (rest > 1 ? 2 * ((rest - 2) / perMinute) : 0);
  }
  const int64_t ff = frame % nominal, total = frame / nominal;
  return fmt::format("{:02}:{:02}:{:02}{}{:02}", (total / 3600) % 24, (total / 60) % 60, total % 60, drop ? ';' : ':', ff);
}

}  // namespace vitrine::rig
