#include "rig/timecode.h"

#include <fmt/format.h>

namespace vitrine::rig {
namespace {

// 29.97 drop-frame: a ten-minute block holds 10 x 1800 labels less 9 x 2 dropped.
constexpr int64_t kDropBlock = 17982, kDropMinute = 1798;

}  // namespace

int labelFps(FrameRate rate) {
  switch (rate) {
    case FrameRate::Fps24: return 24;
    case FrameRate::Fps25: return 25;
    default: return 30;
  }
}

double realFps(FrameRate rate) { return rate == FrameRate::Fps2997Drop ? 30000.0 / 1001.0 : labelFps(rate); }

const char* rateName(FrameRate rate) {
  switch (rate) {
    case FrameRate::Fps24: return "24";
    case FrameRate::Fps25: return "25";
    case FrameRate::Fps2997Drop: return "29.97df";
    default: return "30";
  }
}

int64_t framesPerDay(FrameRate rate) {
  return rate == FrameRate::Fps2997Drop ? 24 * 6 * kDropBlock : int64_t(86400) * labelFps(rate);
}

std::optional<int64_t> frameCount(const Timecode& t, FrameRate rate) {
  const int fps = labelFps(rate);
  if (t.hours < 0 || t.hours > 23 || t.minutes < 0 || t.minutes > 59 || t.seconds < 0 || t.seconds > 59 ||
      t.frames < 0 || t.frames >= fps)
    return std::nullopt;
  const int64_t nominal = (int64_t(t.hours) * 3600 + t.minutes * 60 + t.seconds) * fps + t.frames;
  if (rate != FrameRate::Fps2997Drop) return nominal;
  if (t.seconds == 0 && t.frames < 2 && t.minutes % 10 != 0) return std::nullopt;  // a dropped label
  const int64_t minutes = int64_t(t.hours) * 60 + t.minutes;
  return nominal - 2 * (minutes - minutes / 10);
}

Timecode labelOf(int64_t frames, FrameRate rate) {
  const int64_t day = framesPerDay(rate);
  frames %= day;
  if (frames < 0) frames += day;
  if (rate == FrameRate::Fps2997Drop) {
    const int64_t blocks = frames / kDropBlock, rest = frames % kDropBlock;
    frames += 18 * blocks + (rest >= 2 ? 2 * ((rest - 2) / kDropMinute) : 0);
  }
  const int fps = labelFps(rate);
  const int64_t secondsTotal = frames / fps;
  return {int(secondsTotal / 3600), int(secondsTotal / 60 % 60), int(secondsTotal % 60), int(frames % fps)};
}

double secondsOf(int64_t frames, FrameRate rate) { return double(frames) / realFps(rate); }

std::string formatTimecode(const Timecode& t) {
  return fmt::format("{:02}:{:02}:{:02}:{:02}", t.hours, t.minutes, t.seconds, t.frames);
}

std::optional<Timecode> parseTimecode(std::string_view text, std::string* error) {
  const auto fail = [&](std::string why) -> std::optional<Timecode> {
    if (error) *error = std::move(why);
    return std::nullopt;
  };
  const auto digits = [&](size_t at) { return (text[at] - '0') * 10 + (text[at + 1] - '0'); };
  bool shaped = text.size() == 11;
  for (size_t i = 0; shaped && i < 11; ++i) {
    const char c = text[i];
    shaped = i % 3 == 2 ? (c == ':' || (i == 8 && (c == ';' || c == '.'))) : (c >= '0' && c <= '9');
  }
  if (!shaped) return fail("a timecode is HH:MM:SS:FF, two digits each (e.g. 00:01:30:00)");
  const Timecode t{digits(0), digits(3), digits(6), digits(9)};
  if (t.hours > 23) return fail("its hours are over 23");
  if (t.minutes > 59) return fail("its minutes are over 59");
  if (t.seconds > 59) return fail("its seconds are over 59");
  if (t.frames > 29) return fail("its frames are over 29 (no rate has more than 30 a second)");
  return t;
}

}  // namespace vitrine::rig
