// A playlist chased by timecode: its `at HH:MM:SS:FF` lines (src/host/gallery/playlist.h), the chase
// (src/host/gallery/timecode_chase.h) on its own, and LTC from libltc's encoder through the reader
// (src/rig/ltc_reader.h) into the chase: each line starts on its frame, a locate cuts, a lost
// timecode free-runs.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "host/gallery/kiosk.h"
#include "host/gallery/playlist.h"
#include "host/gallery/timecode_chase.h"
#include "rig/ltc_reader.h"
#include "support/ltc_signal.h"

namespace vitrine::host {
namespace {

const PlaylistChecks kChaseChecks{[](std::string_view scene) { return scene == "kifs" || scene == "noodles"; },
                             [](std::string_view scene, std::string_view name) {
                               return scene == "kifs" && name == "sphere" ? std::string() : "no preset '" + std::string(name) + "'";
                             }};

std::string chaseRefusal(const std::string& text) {
  try {
    parsePlaylist(text, "p.txt", kChaseChecks);
  } catch (const Error& error) {
    return error.what();
  }
  return "accepted";
}

TEST(ChasedPlaylist, AtLinesGiveTheirFrames) {
  const auto entries = parsePlaylist("# the show\nat 00:00:00:00 kifs sphere\nat 00:01:30:12  noodles\n", "p.txt", kChaseChecks);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_TRUE(chasedByTimecode(entries));
  EXPECT_EQ(entries[0].scene, "kifs");
  EXPECT_EQ(entries[0].preset, "sphere");
  EXPECT_EQ(entries[1].at, (rig::Timecode{0, 1, 30, 12}));
  EXPECT_EQ(entries[1].preset, "");
  EXPECT_FALSE(chasedByTimecode(parsePlaylist("kifs 10\n", "p.txt", kChaseChecks)));
}

TEST(ChasedPlaylist, RefusesWhatCannotBeChased) {
  EXPECT_EQ(chaseRefusal("at 00:00:00:00 kifs\nnoodles 10\n"),
            "p.txt:2: a playlist is chased by timecode ('at HH:MM:SS:FF SCENE [PRESET]' on every line) or timed by "
            "dwells ('SCENE [PRESET] SECONDS' on every line), not both.");
  EXPECT_EQ(chaseRefusal("at 00:01:00:00 kifs\nat 00:00:59:29 noodles\n"),
            "p.txt:2: at 00:00:59:29 is not after the line before's 00:01:00:00; chased lines go in time order.");
  EXPECT_EQ(chaseRefusal("at 25:00:00:00 kifs\n"), "p.txt:1: 'at 25:00:00:00': its hours are over 23.");
  EXPECT_EQ(chaseRefusal("at 00:00:00:31 kifs\n"),
            "p.txt:1: 'at 00:00:00:31': its frames are over 29 (no rate has more than 30 a second).");
  EXPECT_EQ(chaseRefusal("at 1:30 kifs\n"),
            "p.txt:1: 'at 1:30': a timecode is HH:MM:SS:FF, two digits each (e.g. 00:01:30:00).");
  EXPECT_EQ(chaseRefusal("at 00:00:10:00\n"),
            "p.txt:1: 'at TIMECODE' wants a scene after it (e.g. 'at 00:01:30:00 kifs sphere').");
  EXPECT_EQ(chaseRefusal("at 00:00:10:00 kifs nothing\n"), "p.txt:1: no preset 'nothing'.");
}

rig::TimecodePosition tc(int64_t frames, rig::FrameRate rate = rig::FrameRate::Fps25) { return {frames, rate, 0.0, 1}; }

TEST(TimecodeChase, EachLineStartsOnItsFrame) {
  for (const rig::FrameRate rate : {rig::FrameRate::Fps24, rig::FrameRate::Fps25, rig::FrameRate::Fps2997Drop}) {
    TimecodeChase chase({{0, 0, 0, 0}, {0, 0, 1, 0}, {0, 1, 0, 2}, {0, 1, 0, 20}});
    std::vector<std::pair<int64_t, size_t>> cues;
    const int64_t from = *rig::frameCount({0, 0, 0, 10}, rate), to = *rig::frameCount({0, 1, 1, 0}, rate);
    for (int64_t f = from; f <= to; ++f)
      if (const auto step = chase.advance(tc(f, rate), true, 1.0 / rig::realFps(rate)); step.cue) {
        EXPECT_FALSE(step.cut) << rig::rateName(rate) << " frame " << f;
        cues.emplace_back(f, *step.cue);
      }
    const std::vector<std::pair<int64_t, size_t>> expected{{rig::labelFps(rate), 1},
                                                           {*rig::frameCount({0, 1, 0, 2}, rate), 2},
                                                           {*rig::frameCount({0, 1, 0, 20}, rate), 3}};
    EXPECT_EQ(cues, expected) << rig::rateName(rate);
  }
  // A frame that 25 fps lacks starts on the next second; a dropped 29.97 label on the minute's first.
  TimecodeChase odd({{0, 0, 0, 0}, {0, 0, 4, 27}, {0, 1, 0, 0}});
  EXPECT_EQ(odd.startFrame(1, rig::FrameRate::Fps25), 125);
  EXPECT_EQ(odd.startFrame(2, rig::FrameRate::Fps2997Drop), 1800);
}

TEST(TimecodeChase, ALocateCutsAndALostTimecodeFreeRuns) {
  TimecodeChase chase({{0, 0, 0, 0}, {0, 0, 10, 0}, {0, 0, 20, 0}});
  EXPECT_EQ(chase.status(), "waiting for timecode on line 1 of 3");
  EXPECT_FALSE(chase.advance(std::nullopt, false, 0.04).cue);
  // The first timecode lands in the middle of the show: a cut to its line.
  auto step = chase.advance(tc(15 * 25), true, 0.04);
  ASSERT_TRUE(step.cue);
  EXPECT_EQ(*step.cue, 1u);
  EXPECT_TRUE(step.cut);
  // Located back to the top: a cut.
  step = chase.advance(tc(2 * 25), true, 0.04);
  EXPECT_EQ(step.cue, 0u);
  EXPECT_TRUE(step.cut);
  // Running to 00:00:09:20, then lost: the chase runs on by itself and starts line 2 on 00:00:10:00.
  int64_t f = 2 * 25;
  for (; f <= 9 * 25 + 20; ++f) chase.advance(tc(f), true, 0.04);
  EXPECT_EQ(chase.status(), "following 00:00:09:20 (25 fps), line 1 of 3");
  int steps = 0;  // the source holds the last frame it had
  while (!(step = chase.advance(tc(f - 1), false, 0.04)).cue && steps < 100) ++steps;
  EXPECT_EQ(steps, 4);  // :21 :22 :23 :24, then 10:00
  EXPECT_EQ(*step.cue, 1u);
  EXPECT_FALSE(step.cut);
  EXPECT_TRUE(chase.freeRunning());
  EXPECT_EQ(chase.status().rfind("timecode lost 0 s ago: free-running at 00:00:10:00 (25 fps), line 2 of 3", 0), 0u)
      << chase.status();
  // The timecode comes back where the free-run is: no cut. Far from it: a cut.
  EXPECT_FALSE(chase.advance(tc(10 * 25 + 1), true, 0.04).cue);
  EXPECT_FALSE(chase.freeRunning());
  step = chase.advance(tc(25 * 25), true, 0.04);
  EXPECT_EQ(step.cue, 2u);
  EXPECT_TRUE(step.cut);
  // Stopped, then located (a full frame): followed, cut, and parked there rather than free-run.
  chase.advance(tc(25 * 25), false, 0.04);
  step = chase.advance(rig::TimecodePosition{12 * 25, rig::FrameRate::Fps25, 0.0, 0}, false, 0.04);
  EXPECT_EQ(step.cue, 1u);
  EXPECT_TRUE(step.cut);
  for (int i = 0; i < 100; ++i) chase.advance(rig::TimecodePosition{12 * 25, rig::FrameRate::Fps25, 0.0, 0}, false, 0.04);
  EXPECT_EQ(chase.status(), "parked at 00:00:12:00 (25 fps), line 2 of 3");
}

// The kiosk's schedule takes a cue whatever its dwell and a person's touch: the fade begins at once,
// and a cue during a fade ends that fade first.
TEST(TimecodeChase, TheScheduleFadesInACuedLine) {
  KioskSchedule schedule(std::vector<double>{kMaxPlaylistDwell, kMaxPlaylistDwell, kMaxPlaylistDwell}, 0,
                         {kMaxPlaylistDwell, 2.0, 30.0});
  EXPECT_FALSE(schedule.advance(1.0, true).begin);
  schedule.cue(2);
  auto plan = schedule.advance(0.02, true);
  EXPECT_EQ(plan.begin, 2u);
  plan = schedule.advance(0.5, false);
  EXPECT_FLOAT_EQ(*plan.fade, 0.25f);
  schedule.cue(1);
  EXPECT_TRUE(schedule.advance(0.02, false).finish);
  EXPECT_EQ(schedule.current(), 2u);
  EXPECT_EQ(schedule.advance(0.02, false).begin, 1u);
}

// LTC from libltc's encoder, played a 60 fps step at a time through the reader into the chase: each cue
// comes in the step during which its line's frame begins.
TEST(TimecodeChase, LtcStartsEachLineOnItsFrame) {
  for (const rig::FrameRate rate : {rig::FrameRate::Fps25, rig::FrameRate::Fps2997Drop}) {
    constexpr double kRate = 48000.0;
    const rig::Timecode start{0, 0, 59, 0};
    const std::vector<rig::Timecode> lines{{0, 0, 0, 0}, {0, 1, 0, 2}, {0, 1, 1, 10}};
    const auto samples = test::ltcSignal(kRate, rate, start, int(3 * rig::realFps(rate)), 0.0123);
    const double lead = std::floor(0.0123 * kRate), perFrame = kRate / rig::realFps(rate);
    rig::LtcReader reader(kRate);
    TimecodeChase chase(lines);
    const size_t step = 800;
    std::vector<std::pair<size_t, size_t>> cues;  // (stream sample at the step's end, line)
    for (size_t end = step; end <= samples.size(); end += step) {
      reader.push(std::span(samples.data() + end - step, step));
      if (const auto cue = chase.advance(reader.position(), reader.locked(), step / kRate).cue) cues.emplace_back(end, *cue);
    }
    const int64_t first = *rig::frameCount(start, rate);
    ASSERT_EQ(cues.size(), 2u) << rig::rateName(rate);
    for (size_t i = 0; i < 2; ++i) {
      const double begins = lead + double(*rig::frameCount(lines[i + 1], rate) - first) * perFrame;
      EXPECT_EQ(cues[i].second, i + 1);
      EXPECT_GE(double(cues[i].first), begins) << rig::rateName(rate) << " line " << i + 1;
      EXPECT_LT(double(cues[i].first), begins + double(step)) << rig::rateName(rate) << " line " << i + 1;
    }
  }
}

}  // namespace
}  // namespace vitrine::host
