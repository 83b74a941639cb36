// Bars of Link's timeline (rig/bar_timing.h), the gate that holds a scene switch for the next bar, the
// kiosk holding a due fade for it, and the link.* sources.
#include "host/gallery/kiosk.h"
#include "host/live_link.h"
#include "live/mapping.h"
#include "rig/bar_timing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace vitrine {
namespace {

using rig::Micros;

TEST(LinkBars, BarAndPhaseOfABeat) {
  EXPECT_EQ(rig::barOf(0.0, 4.0), 0);
  EXPECT_EQ(rig::barOf(3.999, 4.0), 0);
  EXPECT_EQ(rig::barOf(4.0, 4.0), 1);
  EXPECT_EQ(rig::barOf(-0.5, 4.0), -1);  // Link's beats run negative before a session's start
  EXPECT_DOUBLE_EQ(rig::phaseOf(9.5, 4.0), 1.5);
  EXPECT_DOUBLE_EQ(rig::phaseOf(-0.5, 4.0), 3.5);
  EXPECT_DOUBLE_EQ(rig::phaseOf(7.25, 3.0), 1.25);  // three beats a bar
  EXPECT_LT(rig::phaseOf(std::nextafter(8.0, 0.0), 4.0), 4.0);
}

TEST(LinkBars, TheNextBarStartsOnTheQuantum) {
  EXPECT_DOUBLE_EQ(rig::nextBarBeat(5.2, 4.0), 8.0);
  EXPECT_DOUBLE_EQ(rig::nextBarBeat(8.0, 4.0), 12.0);  // asked on a bar's first beat: the next one
  EXPECT_DOUBLE_EQ(rig::nextBarBeat(-1.0, 4.0), 0.0);
  EXPECT_DOUBLE_EQ(rig::nextBarBeat(13.0, 6.0), 18.0);
}

TEST(LinkBars, TheNextBarInHostTime) {
  // 120 BPM: half a second a beat; at beat 6 of 4-beat bars the next bar (beat 8) is 1 s away.
  EXPECT_EQ(rig::nextBarTime(Micros(5'000'000), 6.0, 120.0, 4.0), Micros(6'000'000));
  // 90 BPM, at beat 1.5 of 3-beat bars: 1.5 beats of 2/3 s.
  EXPECT_EQ(rig::nextBarTime(Micros(0), 1.5, 90.0, 3.0), Micros(1'000'000));
}

TEST(LinkBars, TheGateOpensOnceABarBegins) {
  rig::BarGate gate;
  EXPECT_FALSE(gate.observe(5.0, 4.0));  // the first look starts nothing
  EXPECT_FALSE(gate.observe(6.0, 4.0));
  EXPECT_FALSE(gate.observe(7.99, 4.0));
  EXPECT_EQ(gate.observe(8.01, 4.0), 2);  // bar 2 began between the looks
  EXPECT_EQ(gate.lastBeat(), 8.01);
  EXPECT_FALSE(gate.observe(8.5, 4.0));   // once per bar
  EXPECT_EQ(gate.observe(17.0, 4.0), 4);  // a long frame over two bar lines: the bar now
}

TEST(LinkBars, ATimelineJumpingBackStartsNoBar) {
  rig::BarGate gate;
  gate.observe(30.0, 4.0);
  EXPECT_FALSE(gate.observe(2.5, 4.0));  // a session realigned on joining
  EXPECT_FALSE(gate.observe(3.5, 4.0));
  EXPECT_EQ(gate.observe(4.1, 4.0), 1);  // the next real bar line
  EXPECT_FALSE(gate.observe(std::numeric_limits<double>::quiet_NaN(), 4.0));
  EXPECT_FALSE(gate.observe(std::numeric_limits<double>::infinity(), 4.0));
  EXPECT_FALSE(gate.observe(9.0, 0.0));  // no quantum
  EXPECT_EQ(gate.observe(8.2, 4.0), 2);
}

TEST(LinkBars, TheKioskHoldsADueFadeForTheBar) {
  host::KioskSchedule schedule(3, 0, {.dwell = 1.0, .fade = 0.5, .idle = 10.0});
  EXPECT_FALSE(schedule.advance(1.2, false, /*mayBegin=*/false).begin);  // due, but the bar has not come
  EXPECT_FALSE(schedule.advance(0.3, false, false).begin);
  const auto plan = schedule.advance(0.01, false, true);  // the bar line
  ASSERT_TRUE(plan.begin);
  EXPECT_EQ(*plan.begin, 1u);
  EXPECT_FALSE(schedule.advance(0.6, false, false).begin);  // a fade under way finishes off the bar
  EXPECT_EQ(schedule.current(), 1u);
}

TEST(LinkSources, NamesAreChecked) {
  for (const char* name : {"link.tempo", "link.beat", "link.phase", "link.bar", "link.playing", "link.pulse"})
    EXPECT_EQ(live::checkSourceName(name), "") << name;
  EXPECT_NE(live::checkSourceName("link.swing").find("Ableton Link sources are"), std::string::npos);
  EXPECT_NE(live::checkSourceName("link.beat.2").find("Ableton Link sources are"), std::string::npos);
  EXPECT_NE(live::checkSourceName("nope.x").find("link.tempo|beat|phase|bar|playing|pulse"), std::string::npos);
}

TEST(LinkSources, EachReadsZeroToOne) {
  live::SourceBank sources;
  rig::LinkReading now;
  now.bpm = 120.0;
  now.beat = 13.25;
  now.phase = rig::phaseOf(now.beat, 4.0);
  now.bar = rig::barOf(now.beat, 4.0);
  now.playing = true;
  now.beatBegan = true;
  host::setLinkSources(now, /*lastBar=*/2, 4.0, sources);
  EXPECT_FLOAT_EQ(sources.value("link.tempo"), 0.5f);
  EXPECT_FLOAT_EQ(sources.value("link.beat"), 0.25f);
  EXPECT_FLOAT_EQ(sources.value("link.phase"), 1.25f / 4.0f);
  EXPECT_FLOAT_EQ(sources.value("link.bar"), 1.0f);  // bar 3 began
  EXPECT_FLOAT_EQ(sources.value("link.pulse"), 1.0f);
  EXPECT_FLOAT_EQ(sources.value("link.playing"), 1.0f);
  now.beatBegan = false;
  now.bpm = 480.0;  // beyond the range: clamped
  host::setLinkSources(now, /*lastBar=*/3, 4.0, sources);
  EXPECT_FLOAT_EQ(sources.value("link.bar"), 0.0f);
  EXPECT_FLOAT_EQ(sources.value("link.pulse"), 0.0f);
  EXPECT_FLOAT_EQ(sources.value("link.tempo"), 1.0f);
}

}  // namespace
}  // namespace vitrine
