#pragma once
// SMPTE timecode as MIDI timecode and LTC carry it: a label HH:MM:SS:FF at one of four frame rates,
// and the frame count since 00:00:00:00 it stands for. At 29.97 drop-frame the labels ;00 and ;01 of
// every minute but each tenth are skipped, so the label keeps to the wall clock; every other rate
// counts each label. Pure arithmetic, shared by the MTC parser, the LTC reader and the playlist.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace vitrine::rig {

enum class FrameRate { Fps24, Fps25, Fps2997Drop, Fps30 };

struct Timecode {
  int hours = 0, minutes = 0, seconds = 0, frames = 0;
  bool operator==(const Timecode&) const = default;
};

// Frames a second as labels count them (24, 25, 30, 30) and as the clock runs (29.97 drop: 30000/1001).
int labelFps(FrameRate rate);
double realFps(FrameRate rate);
const char* rateName(FrameRate rate);  // "24", "25", "29.97df", "30"

// Frames in a day at `rate`: a count wraps there, as the labels do after 23:59:59.
int64_t framesPerDay(FrameRate rate);

// The frame count of a label; none when the label does not exist at `rate` (hours over 23, minutes or
// seconds over 59, a frame at or over the rate, a dropped label of 29.97 drop-frame).
std::optional<int64_t> frameCount(const Timecode& label, FrameRate rate);
// The label of a frame count, wrapped into one day.
Timecode labelOf(int64_t frames, FrameRate rate);
// Seconds since 00:00:00:00 of a frame count, on the real clock.
double secondsOf(int64_t frames, FrameRate rate);

// "HH:MM:SS:FF" (the separator ':' at every rate).
std::string formatTimecode(const Timecode& label);
// "HH:MM:SS:FF" (';' also taken before the frames, as drop-frame is often written), two digits each,
// hours 0..23, minutes and seconds 0..59, frames 0..29; nullopt with the reason in *error.
std::optional<Timecode> parseTimecode(std::string_view text, std::string* error);

}  // namespace vitrine::rig
