// The show's clocks over MIDI from timed byte streams (src/rig/midi_timing.h): MIDI clock's tempo,
// jitter, beat and transport, MIDI timecode frame-exact at every rate and in both directions, the
// labels' arithmetic (src/rig/timecode.h), and hostile bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "rig/midi_timing.h"
#include "rig/timecode.h"

namespace vitrine::rig {
namespace {

// Pulses at `bpm` from `start` for `beats`, each late or early by a normal jitter of `sigmaMs`.
double sendPulses(MidiTiming& timing, double start, double bpm, double beats, double sigmaMs, std::mt19937& random) {
  std::normal_distribution<double> jitter(0.0, sigmaMs / 1000.0);
  const double interval = 60.0 / bpm / 24.0;
  const int pulses = int(std::lround(beats * 24.0));
  for (int i = 0; i < pulses; ++i) timing.feed(start + i * interval + (sigmaMs > 0 ? jitter(random) : 0.0), 0xF8);
  return start + pulses * interval;
}

TEST(MidiClock, TempoWithinHalfABeatAMinuteThroughUsbJitter) {
  for (const double bpm : {120.0, 174.0, 87.5}) {
    std::mt19937 random(7);
    MidiTiming timing;
    const double end = sendPulses(timing, 100.0, bpm, 8, 1.0, random);
    ASSERT_TRUE(timing.clock().bpm()) << bpm;
    EXPECT_NEAR(*timing.clock().bpm(), bpm, 0.5) << bpm;
    // One millisecond of jitter each way is what the fitted line sees; the pulses' own spread.
    EXPECT_GT(timing.clock().jitterMs(), 0.5) << bpm;
    EXPECT_LT(timing.clock().jitterMs(), 1.6) << bpm;
    EXPECT_TRUE(timing.clock().locked(end));
    EXPECT_TRUE(timing.clock().status(end).locked);
    EXPECT_EQ(*timing.clock().status(end).bpm, *timing.clock().bpm());
  }
}

// Two milliseconds of jitter at 174 BPM is a seventh of a pulse: averaged, not taken for a tempo change
// at every other pulse (which had refitted from a few pulses and read up to 20 BPM off).
TEST(MidiClock, AShakyClockIsAveragedNotChased) {
  double worst = 0.0;
  for (unsigned seed = 0; seed < 50; ++seed) {
    std::mt19937 random(seed);
    MidiTiming timing;
    sendPulses(timing, 0.0, 174.0, 8, 2.0, random);
    worst = std::max(worst, std::abs(*timing.clock().bpm() - 174.0));
  }
  EXPECT_LT(worst, 0.5);
}

TEST(MidiClock, FollowsATempoChangeWithinTwoBeats) {
  std::mt19937 random(3);
  MidiTiming timing;
  double t = sendPulses(timing, 10.0, 120.0, 8, 0.5, random);
  t = sendPulses(timing, t, 174.0, 2, 0.5, random);
  ASSERT_TRUE(timing.clock().bpm());
  EXPECT_NEAR(*timing.clock().bpm(), 174.0, 0.5);
  sendPulses(timing, t, 174.0, 4, 0.5, random);
  EXPECT_NEAR(*timing.clock().bpm(), 174.0, 0.2);
}

TEST(MidiClock, StartStopContinueAndSongPosition) {
  MidiTiming timing;
  const double interval = 60.0 / 120.0 / 24.0;  // 120 BPM
  timing.feed(0.0, 0xFA);                         // start: the next pulse is beat 0
  for (int i = 0; i < 48; ++i) timing.feed(i * interval, 0xF8);
  double last = 47 * interval;
  EXPECT_TRUE(timing.clock().running());
  EXPECT_NEAR(timing.clock().beat(last), 47.0 / 24.0, 1e-9);
  EXPECT_NEAR(timing.clock().beat(last + interval / 2), 47.5 / 24.0, 1e-6);  // between pulses, at the tempo
  timing.feed(last + 0.001, 0xFC);                                            // stop: the beat holds
  EXPECT_FALSE(timing.clock().running());
  EXPECT_NEAR(timing.clock().beat(last + 0.5), 47.0 / 24.0, 1e-9);
  // Song position 16 sixteenths (beat 4), then continue: the next pulse is beat 4.
  const uint8_t position[] = {0xF2, 16, 0};
  timing.feed(last + 0.01, position);
  timing.feed(last + 0.02, 0xFB);
  timing.feed(last + 0.03, 0xF8);
  EXPECT_NEAR(timing.clock().beat(last + 0.03), 4.0, 1e-9);
  timing.feed(last + 0.03 + interval, 0xF8);
  EXPECT_NEAR(timing.clock().beat(last + 0.03 + interval), 4.0 + 1.0 / 24.0, 1e-9);
}

TEST(MidiClock, LostClockRunsOnAtItsTempoAndSaysSo) {
  std::mt19937 random(1);
  MidiTiming timing;
  const double end = sendPulses(timing, 0.0, 120.0, 4, 0.0, random);
  const double last = end - 60.0 / 120.0 / 24.0;
  const double beatAtLast = timing.clock().beat(last);
  const ClockStatus lost = timing.clock().status(last + 3.0);
  EXPECT_FALSE(lost.locked);
  EXPECT_NE(lost.note.find("lost 3 s ago: own clock at 120.0 BPM"), std::string::npos) << lost.note;
  // Smooth: the beat runs on at two a second, no jump when the clock is declared lost.
  EXPECT_NEAR(timing.clock().beat(last + 0.99), beatAtLast + 1.98, 1e-6);
  EXPECT_NEAR(timing.clock().beat(last + 1.01), beatAtLast + 2.02, 1e-6);
  // Pulses that come back carry on from where the flywheel is.
  timing.feed(last + 3.0, 0xF8);
  EXPECT_NEAR(timing.clock().beat(last + 3.0), beatAtLast + 6.0, 1.0 / 24.0);
}

TEST(MidiClock, TempoSurvivesGarbageBetweenThePulses) {
  std::mt19937 random(11);
  std::uniform_int_distribution<int> byte(0, 255);
  MidiTiming timing;
  const double interval = 60.0 / 174.0 / 24.0;
  for (int i = 0; i < 24 * 8; ++i) {
    const double t = 5.0 + i * interval;
    // Between pulses: stray data bytes, a note-on cut short, running status, an unfinished SysEx.
    const uint8_t noise[] = {uint8_t(byte(random) & 0x7F), 0x90, 0x3C, 0x91, 0x40, 0x7F, 0x41, 0x7F, 0xF0, 0x01};
    timing.feed(t - interval / 2, noise);
    timing.feed(t, 0xF8);
  }
  ASSERT_TRUE(timing.clock().bpm());
  EXPECT_NEAR(*timing.clock().bpm(), 174.0, 0.5);
  EXPECT_GT(timing.refused(), 0u);
  EXPECT_FALSE(timing.trouble().empty());
}

TEST(MidiTiming, RandomBytesNeverBreakIt) {
  std::mt19937 random(5);
  std::uniform_int_distribution<int> byte(0, 255);
  MidiTiming timing;
  for (int i = 0; i < 200000; ++i) timing.feed(i * 0.0001, uint8_t(byte(random)));
  if (const auto at = timing.mtc().position()) {
    EXPECT_GE(at->frames, 0);
    EXPECT_LT(at->frames, framesPerDay(at->rate));
  }
  if (const auto bpm = timing.clock().bpm()) {
    EXPECT_TRUE(*bpm >= MidiClock::kMinBpm && *bpm <= MidiClock::kMaxBpm);
  }
  EXPECT_TRUE(std::isfinite(timing.clock().beat(30.0)));
  EXPECT_GT(timing.refused(), 0u);
}

// --- MIDI timecode

constexpr int rateBits(FrameRate rate) {
  return rate == FrameRate::Fps24 ? 0 : rate == FrameRate::Fps25 ? 1 : rate == FrameRate::Fps2997Drop ? 2 : 3;
}

uint8_t quarterFrame(const Timecode& t, FrameRate rate, int piece) {
  const int values[8] = {t.frames & 15, t.frames >> 4, t.seconds & 15, t.seconds >> 4,
                         t.minutes & 15, t.minutes >> 4, t.hours & 15, (t.hours >> 4) | rateBits(rate) << 1};
  return uint8_t(piece << 4 | values[piece]);
}

// Quarter frames as a show controller sends them while running forwards from frame `from`: each
// cycle of eight pieces carries the label of its first frame; returns the frame count after.
struct Sent {
  double time;
  int64_t quarters;  // where the position should be after this piece
};
std::vector<Sent> runForwards(MidiTiming& timing, int64_t from, int cycles, FrameRate rate, double start) {
  std::vector<Sent> sent;
  const double quarter = 1.0 / realFps(rate) / 4.0;
  for (int c = 0; c < cycles; ++c) {
    const int64_t frame = from + 2 * c;
    const Timecode label = labelOf(frame, rate);
    for (int piece = 0; piece < 8; ++piece) {
      const double t = start + double((frame - from) * 4 + piece) * quarter;
      const uint8_t bytes[] = {0xF1, quarterFrame(label, rate, piece)};
      timing.feed(t, bytes);
      sent.push_back({t, frame * 4 + piece});
    }
  }
  return sent;
}

TEST(Mtc, FrameExactForwardsAtEveryRate) {
  const struct {
    FrameRate rate;
    Timecode from;
  } cases[] = {{FrameRate::Fps24, {1, 0, 0, 0}},
               {FrameRate::Fps25, {10, 59, 58, 20}},
               {FrameRate::Fps2997Drop, {0, 0, 59, 20}},  // across 00:01:00;02, the first label after a drop
               {FrameRate::Fps30, {23, 59, 59, 10}}};    // across midnight
  for (const auto& c : cases) {
    MidiTiming timing;
    const int64_t from = *frameCount(c.from, c.rate);
    const auto sent = runForwards(timing, from, 30, c.rate, 50.0);
    // Again piece by piece: from the first whole cycle on, every piece lands on its quarter frame.
    MidiTiming replay;
    int checked = 0;
    const double quarter = 1.0 / realFps(c.rate) / 4.0;
    for (size_t i = 0; i < sent.size(); ++i) {
      const int64_t frame = from + 2 * int64_t(i / 8);
      const uint8_t bytes[] = {0xF1, quarterFrame(labelOf(frame, c.rate), c.rate, int(i % 8))};
      replay.feed(50.0 + double(i) * quarter, bytes);
      if (i < 7) continue;
      const auto at = replay.mtc().position();
      ASSERT_TRUE(at) << i;
      const int64_t day = framesPerDay(c.rate);
      EXPECT_EQ(at->frames, (sent[i].quarters / 4) % day) << rateName(c.rate) << " piece " << i;
      EXPECT_DOUBLE_EQ(at->fraction, double(sent[i].quarters % 4) / 4.0);
      EXPECT_EQ(at->rate, c.rate);
      EXPECT_EQ(at->direction, 1);
      ++checked;
    }
    EXPECT_EQ(checked, 30 * 8 - 7);
    EXPECT_TRUE(replay.mtc().locked(sent.back().time));
    EXPECT_EQ(replay.mtc().jumps(), 0u);
    EXPECT_EQ(replay.refused(), 0u);
  }
  // The drop-frame run passes 00:01:00;02 straight after 00:00:59;29.
  MidiTiming timing;
  runForwards(timing, *frameCount({0, 0, 59, 28}, FrameRate::Fps2997Drop), 1, FrameRate::Fps2997Drop, 0.0);
  EXPECT_EQ(formatTimecode(timing.mtc().position()->label()), "00:00:59:29");
  runForwards(timing, *frameCount({0, 0, 59, 28}, FrameRate::Fps2997Drop) + 2, 1, FrameRate::Fps2997Drop, 1.0 / 29.97 * 2);
  EXPECT_EQ(formatTimecode(timing.mtc().position()->label()), "00:01:00:03");
}

TEST(Mtc, BackwardsAndLocate) {
  const FrameRate rate = FrameRate::Fps25;
  const int64_t from = *frameCount({0, 10, 0, 0}, rate);
  MidiTiming timing;
  const double quarter = 1.0 / 25.0 / 4.0;
  double t = 0.0;
  // Backwards: pieces 7..0 of each cycle, the cycles' labels falling two frames each.
  for (int c = 0; c < 6; ++c) {
    const Timecode label = labelOf(from - 2 * c, rate);
    for (int piece = 7; piece >= 0; --piece, t += quarter) {
      const uint8_t bytes[] = {0xF1, quarterFrame(label, rate, piece)};
      timing.feed(t, bytes);
    }
    const auto at = timing.mtc().position();
    ASSERT_TRUE(at);
    EXPECT_EQ(at->frames, from - 2 * c);
    EXPECT_EQ(at->direction, -1);
  }
  EXPECT_EQ(timing.mtc().jumps(), 0u);
  // A full frame locates: parked exactly there, counted as a jump.
  const uint8_t full[] = {0xF0, 0x7F, 0x7F, 0x01, 0x01, uint8_t(1 << 5 | 2), 30, 15, 12, 0xF7};
  timing.feed(t + 0.5, full);
  const auto at = timing.mtc().position();
  ASSERT_TRUE(at);
  EXPECT_EQ(formatTimecode(at->label()), "02:30:15:12");
  EXPECT_EQ(at->direction, 0);
  EXPECT_EQ(timing.mtc().jumps(), 1u);
  EXPECT_FALSE(timing.mtc().locked(t + 0.5));
  // Quarter frames running on from elsewhere: a jump, and the new place frame-exact.
  const int64_t elsewhere = *frameCount({3, 0, 0, 0}, rate);
  runForwards(timing, elsewhere, 2, rate, t + 1.0);
  EXPECT_EQ(timing.mtc().position()->frames, elsewhere + 3);  // the second cycle's piece 7: frame + 1.75
  EXPECT_TRUE(timing.mtc().locked(t + 1.0 + 15 * quarter));
}

TEST(Mtc, ImpossibleTimecodeIsRefusedAndMovesNothing) {
  const FrameRate rate = FrameRate::Fps25;
  MidiTiming timing;
  runForwards(timing, *frameCount({1, 2, 3, 4}, rate), 2, rate, 0.0);
  const int64_t before = timing.mtc().position()->frames;
  // Hours 25, frame 27 at 25 fps, a dropped drop-frame label, a full frame with minute 61.
  for (const Timecode bad : {Timecode{25, 0, 0, 0}, Timecode{1, 0, 0, 27}}) {
    MidiTiming fresh;
    for (int piece = 0; piece < 8; ++piece) {
      const uint8_t bytes[] = {0xF1, quarterFrame(bad, rate, piece)};
      fresh.feed(piece * 0.01, bytes);
    }
    EXPECT_FALSE(fresh.mtc().position());
    EXPECT_NE(fresh.trouble().find("impossible timecode"), std::string::npos) << fresh.trouble();
  }
  MidiTiming drop;
  for (int piece = 0; piece < 8; ++piece) {
    const uint8_t bytes[] = {0xF1, quarterFrame({0, 1, 0, 0}, FrameRate::Fps2997Drop, piece)};
    drop.feed(piece * 0.01, bytes);
  }
  EXPECT_EQ(drop.trouble(), "impossible timecode 00:01:00:00 at 29.97df fps");
  const uint8_t full[] = {0xF0, 0x7F, 0x7F, 0x01, 0x01, 1 << 5, 61, 0, 0, 0xF7};
  timing.feed(1.0, full);
  EXPECT_EQ(timing.trouble(), "impossible full-frame timecode 00:61:00:00 at 25 fps");
  // A full frame cut short by another status, one too short, pieces out of order.
  const uint8_t cut[] = {0xF0, 0x7F, 0x7F, 0x01, 0x01, 0x20, 0xF8, 0x90};  // real time may sit inside
  timing.feed(1.1, cut);
  EXPECT_EQ(timing.trouble(), "a SysEx cut short by status 0x90");
  const uint8_t shortFull[] = {0xF0, 0x7F, 0x7F, 0x01, 0x01, 0x20, 0x01, 0xF7};
  timing.feed(1.2, shortFull);
  EXPECT_EQ(timing.trouble(), "an MTC full frame of 8 bytes, not 10");
  EXPECT_EQ(timing.mtc().position()->frames, before);
}

TEST(Timecode, LabelsAndCountsAgree) {
  for (const FrameRate rate : {FrameRate::Fps24, FrameRate::Fps25, FrameRate::Fps2997Drop, FrameRate::Fps30})
    for (int64_t frames = 0; frames < framesPerDay(rate); frames += 997) {
      const auto back = frameCount(labelOf(frames, rate), rate);
      ASSERT_TRUE(back) << rateName(rate) << " " << frames;
      ASSERT_EQ(*back, frames) << rateName(rate);
    }
  EXPECT_EQ(framesPerDay(FrameRate::Fps2997Drop), 2589408);  // 24 h x 107892 frames
  EXPECT_EQ(*frameCount({0, 10, 0, 0}, FrameRate::Fps2997Drop), 17982);
  EXPECT_FALSE(frameCount({0, 1, 0, 1}, FrameRate::Fps2997Drop));
  EXPECT_TRUE(frameCount({0, 10, 0, 0}, FrameRate::Fps2997Drop));
  EXPECT_FALSE(frameCount({0, 0, 0, 25}, FrameRate::Fps25));
  EXPECT_NEAR(secondsOf(*frameCount({1, 0, 0, 0}, FrameRate::Fps2997Drop), FrameRate::Fps2997Drop), 3600.0, 0.004);
  std::string why;
  EXPECT_EQ(parseTimecode("00:01:30;12", &why), (Timecode{0, 1, 30, 12}));
  EXPECT_FALSE(parseTimecode("24:00:00:00", &why));
  EXPECT_EQ(why, "its hours are over 23");
  EXPECT_FALSE(parseTimecode("1:00:00:00", &why));
  EXPECT_FALSE(parseTimecode("00:00:00:30", &why));
}

}  // namespace
}  // namespace vitrine::rig
