// What the gallery tells of a Link session (rig/link_watch.h): peers, the transport, tempo news at most
// once a second, a flood named in the status, the jitter of a straight and of a jumping timeline.
#include "rig/link_watch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace vitrine::rig {
namespace {

// A reading of a timeline at `bpm` that was at beat 0 at host time 0, `ms` milliseconds in.
LinkReading at(double ms, double bpm = 120.0, size_t peers = 1, bool playing = false) {
  LinkReading r;
  r.hostTime = Micros(int64_t(ms * 1000.0));
  r.bpm = bpm;
  r.beat = ms / 1000.0 * bpm / 60.0;
  r.phase = phaseOf(r.beat, 4.0);
  r.bar = barOf(r.beat, 4.0);
  r.peers = peers;
  r.playing = playing;
  return r;
}

bool saysSomething(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(), [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

TEST(LinkWatch, PeersComeAndGo) {
  LinkWatch watch(4.0);
  watch.observe(at(0, 120, 0));
  EXPECT_TRUE(saysSomething(watch.takeNews(), "no peers yet: own clock at 120.00 BPM"));
  EXPECT_FALSE(watch.status(true).locked);
  EXPECT_EQ(watch.status(true).note, "no peers: own clock");
  watch.observe(at(16, 120, 2));
  EXPECT_TRUE(saysSomething(watch.takeNews(), "2 peers"));
  EXPECT_TRUE(watch.status(true).locked);
  EXPECT_EQ(watch.status(true).note, "2 peers");
  EXPECT_FALSE(watch.status(false).locked);  // switched off: its own clock, whatever the network holds
  EXPECT_EQ(watch.status(false).note, "off: own clock");
  watch.observe(at(32, 120, 0));
  EXPECT_TRUE(saysSomething(watch.takeNews(), "every peer left: own clock from here at 120.00 BPM (beat 0.0640"));
  watch.observe(at(3032, 120, 0));
  EXPECT_EQ(watch.status(true).note, "every peer left 3 s ago: own clock");
  EXPECT_EQ(watch.status(true).bpm, 120.0);
}

TEST(LinkWatch, TheTransport) {
  LinkWatch watch(4.0);
  watch.observe(at(0));
  watch.takeNews();
  watch.observe(at(10, 120, 1, true));
  EXPECT_TRUE(saysSomething(watch.takeNews(), "the transport plays"));
  watch.observe(at(20, 120, 1, false));
  EXPECT_TRUE(saysSomething(watch.takeNews(), "the transport stops"));
}

TEST(LinkWatch, TempoNewsAtMostOnceASecond) {
  LinkWatch watch(4.0);
  watch.observe(at(0));
  watch.takeNews();
  watch.observe(at(10, 96));  // after a quiet spell: said at once
  auto news = watch.takeNews();
  ASSERT_EQ(news.size(), 1u);
  EXPECT_NE(news[0].find("tempo 96.00 BPM"), std::string::npos);
  // A flood: a new tempo every 10 ms for 1.5 s, 150 changes, said once (a second after the last line).
  size_t lines = 0;
  for (int i = 1; i <= 150; ++i) {
    watch.observe(at(10 + i * 10.0, i % 2 ? 140.0 : 100.0));
    lines += watch.takeNews().size();
  }
  EXPECT_EQ(lines, 1u);
  EXPECT_NE(watch.status(true).note.find("1 peer, tempo changing 101 times a second"), std::string::npos);
  // Quiet again: the changes since the last line are told when the second is up, then nothing.
  watch.observe(at(3000, 100.0));
  news = watch.takeNews();
  ASSERT_EQ(news.size(), 1u);
  EXPECT_NE(news[0].find("changes in"), std::string::npos);
  watch.observe(at(4500, 100.0));
  EXPECT_TRUE(watch.takeNews().empty());
  EXPECT_EQ(watch.status(true).note.find("tempo changing"), std::string::npos);
}

TEST(LinkWatch, JitterOfAStraightAndOfAJumpingTimeline) {
  LinkWatch watch(4.0);
  for (int i = 0; i < 120; ++i) watch.observe(at(i * 16.0));
  EXPECT_LT(watch.status(true).jitterMs, 1e-6);
  LinkReading jumped = at(120 * 16.0);
  jumped.beat += 0.002;  // 1 ms at 120 BPM, once
  watch.observe(jumped);
  // One miss of 1 ms among the readings of the last 2 s (125 at 16 ms): RMS 1/sqrt(n).
  EXPECT_NEAR(watch.status(true).jitterMs, 1.0 / std::sqrt(125.0), 0.01);
  // A tempo change bends the timeline on purpose: not jitter.
  LinkWatch changing(4.0);
  changing.observe(at(0, 120));
  changing.observe(at(16, 140));
  EXPECT_LT(changing.status(true).jitterMs, 1e-6);
}

}  // namespace
}  // namespace vitrine::rig
