// LTC read from sound (src/rig/ltc_reader.h): libltc's own encoder writes it (tests/support/ltc_signal.h),
// through a WAV file as --audio-in reads it, and every frame decoded is the frame the generator sent at
// that sample, at 24, 25, 29.97 drop-frame and 30, forwards and backwards.
#include <gtest/gtest.h>

#include <sndfile.h>

#include <cmath>
#include <random>
#include <vector>

#include "live/audio_clip.h"
#include "rig/ltc_reader.h"
#include "support/ltc_signal.h"
#include "support/temp_folder.h"

namespace vitrine::rig {
namespace {

constexpr double kRate = 48000.0;

class Ltc : public test::TempFolderTest {
 protected:
  // The clip as --audio-in reads it, after a round trip through a 16-bit WAV.
  std::vector<float> throughWav(const std::vector<float>& samples) {
    const auto path = folder_ / "ltc.wav";
  SF_INFO info{};
  info.samplerate = int(kRate);
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
  SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
  EXPECT_TRUE(file);
  sf_writef_float(file, samples.data(), sf_count_t(samples.size()));
  sf_close(file);
  return live::monoMix(live::readAudioFile(path));
  }
};

TEST_F(Ltc, FrameExactAtEveryRateThroughAWav) {
  const struct {
    FrameRate rate;
    Timecode start;
  } cases[] = {{FrameRate::Fps24, {10, 0, 0, 0}},
               {FrameRate::Fps25, {1, 0, 59, 0}},
               {FrameRate::Fps2997Drop, {0, 0, 59, 10}},  // through 00:01:00;02
               {FrameRate::Fps30, {23, 59, 59, 0}}};     // through midnight
  for (const auto& c : cases) {
    constexpr int kFrames = 60;
    constexpr double kLeadIn = 0.1;
    const auto samples = throughWav(test::ltcSignal(kRate, c.rate, c.start, kFrames, kLeadIn));
    const int64_t first = *frameCount(c.start, c.rate);
    const double perFrame = kRate / realFps(c.rate), lead = kLeadIn * kRate;
    LtcReader reader(kRate);
    int checked = 0;
    // Fed a step at a time as the simulation clock plays the file (700 samples: the steps' ends fall
    // all through the frames), checked away from the frame boundaries, where either frame is right.
    const size_t step = 700;
    for (size_t at = 0; at + step <= samples.size(); at += step) {
      reader.push(std::span(samples.data() + at, step));
      const auto position = reader.position();
      if (!position) continue;
      const double end = double(at + step);
      const double sent = (end - lead) / perFrame;  // frames the generator has begun since `start`
      const double within = sent - std::floor(sent);
      if (within < 0.02 || within > 0.98 || sent >= kFrames) continue;
      EXPECT_EQ(position->frames, (first + int64_t(std::floor(sent))) % framesPerDay(c.rate))
          << rateName(c.rate) << " at sample " << end;
      EXPECT_EQ(position->rate, c.rate);
      EXPECT_EQ(position->direction, 1);
      ++checked;
    }
    // All but the first two frames (the decoder's first sync word ends the second) and the edges.
    EXPECT_GT(checked, int((kFrames - 2) * perFrame / double(step) * 0.9)) << rateName(c.rate);
    EXPECT_EQ(reader.jumps(), 0u) << rateName(c.rate);
    EXPECT_EQ(reader.refused(), 0u) << rateName(c.rate);
    EXPECT_GE(reader.frames(), uint64_t(kFrames - 2)) << rateName(c.rate);
    EXPECT_LT(reader.jitterMs(), 0.1) << rateName(c.rate);
    const ClockStatus status = reader.status();
    EXPECT_FALSE(status.timecode.empty());
  }
}

TEST_F(Ltc, BackwardsAndALocate) {
  const FrameRate rate = FrameRate::Fps25;
  auto samples = test::ltcSignal(kRate, rate, {0, 5, 0, 0}, 25, 0.0, true);
  LtcReader reader(kRate);
  reader.push(samples);
  ASSERT_TRUE(reader.position());
  EXPECT_EQ(reader.position()->direction, -1);
  // The last frame sent backwards was 00:04:59:01: as its sound ends, the one before it begins.
  EXPECT_EQ(formatTimecode(reader.position()->label()), "00:04:59:00");
  // The generator jumps to 02:00:00:00 and runs forwards: one jump, the new place frame-exact.
  const auto after = test::ltcSignal(kRate, rate, {2, 0, 0, 0}, 10);
  reader.push(after);
  EXPECT_EQ(reader.jumps(), 1u);
  EXPECT_EQ(reader.position()->direction, 1);
  EXPECT_EQ(formatTimecode(reader.position()->label()), "02:00:00:10");  // :09's sound has ended
}

TEST_F(Ltc, SilenceNoiseAndImpossibleLabels) {
  LtcReader reader(kRate);
  std::mt19937 random(9);
  std::uniform_real_distribution<float> noise(-1.0f, 1.0f);
  std::vector<float> junk(48000);
  for (float& s : junk) s = noise(random);
  junk[100] = NAN, junk[200] = INFINITY;
  reader.push(junk);
  EXPECT_FALSE(reader.position());
  EXPECT_EQ(reader.status().note, "no LTC heard in the audio input");
  // 25 fps LTC that counts to frame 27 of a second: frames 25..27 are refused, the rest read.
  LtcReader tolerant(kRate);
  const auto thirty = test::ltcSignal(kRate, FrameRate::Fps30, {0, 0, 0, 20}, 12);
  // Told apart by length alone, thirty frames a second played slower as though at 25: resampled.
  std::vector<float> slowed(size_t(double(thirty.size()) * 30.0 / 25.0));
  for (size_t i = 0; i < slowed.size(); ++i) slowed[i] = thirty[std::min(thirty.size() - 1, size_t(double(i) * 25.0 / 30.0))];
  tolerant.push(slowed);
  EXPECT_GT(tolerant.refused(), 0u);
  EXPECT_NE(tolerant.trouble().find("impossible timecode 00:00:00:2"), std::string::npos) << tolerant.trouble();
  EXPECT_NE(tolerant.trouble().find("at 25 fps"), std::string::npos) << tolerant.trouble();
  // Silence after the code: lost, holding the last frame.
  const auto code = test::ltcSignal(kRate, FrameRate::Fps25, {0, 0, 1, 0}, 10);
  LtcReader stops(kRate);
  stops.push(code);
  EXPECT_TRUE(stops.locked());
  const int64_t last = stops.position()->frames;
  stops.push(std::vector<float>(24000, 0.0f));
  EXPECT_FALSE(stops.locked());
  EXPECT_EQ(stops.position()->frames, last);
  EXPECT_EQ(stops.position()->direction, 0);
  EXPECT_NE(stops.status().note.find("lost"), std::string::npos) << stops.status().note;
}

}  // namespace
}  // namespace vitrine::rig
