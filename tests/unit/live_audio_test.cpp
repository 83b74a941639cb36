// Live audio input: band energies of sines, onsets of a kick track against where the kicks are,
// the tempo and beats of a steady 120 BPM, independence from how samples are split into pushes,
// sound files read and resampled, a file as live input stepped by the simulation clock, and the
// capture device's fallback without a device.
#include <gtest/gtest.h>
#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "audio/wav.h"
#include "core/error.h"
#include "live/audio_analysis.h"
#include "live/audio_capture.h"
#include "live/audio_clip.h"
#include "live/audio_file_input.h"
#include "live/float_ring.h"
#include "support/temp_folder.h"

namespace vitrine::live {
namespace {

constexpr double kRate = 48000.0;
constexpr double kPi = std::numbers::pi;

std::vector<float> sine(double hz, double amplitude, double seconds, double rate = kRate) {
  std::vector<float> out(size_t(std::llround(seconds * rate)));
  for (size_t i = 0; i < out.size(); ++i) out[i] = float(amplitude * std::sin(2.0 * kPi * hz * double(i) / rate));
  return out;
}

// A synthetic kick drum added at `at` seconds: a pitch drop from 160 Hz to 50 Hz under a 60 ms
// decay, with 2 ms of noise for the beater's click. Deterministic (its own little generator).
void addKick(std::vector<float>& track, double at, double rate = kRate) {
  const auto first = size_t(std::llround(at * rate));
  uint32_t noise = 12345;
  double phase = 0;
  for (size_t i = 0; i < size_t(0.3 * rate) && first + i < track.size(); ++i) {
    const double t = double(i) / rate;
    phase += 2.0 * kPi * (50.0 + 110.0 * std::exp(-t / 0.03)) / rate;
    noise = noise * 1664525u + 1013904223u;
    const double click = t < 0.002 ? 0.5 * (double(noise >> 8) / double(1 << 24) * 2.0 - 1.0) : 0.0;
    track[first + i] += float(0.8 * std::exp(-t / 0.06) * std::sin(phase) + click);
  }
}

std::vector<float> kickTrack(double seconds, const std::vector<double>& times) {
  std::vector<float> track(size_t(seconds * kRate), 0.0f);
  for (double t : times) addKick(track, t);
  return track;
}

// The irregular kicks the onset tests look for.
const std::vector<double> kKicks = {0.25, 0.61, 1.02, 1.37, 1.93, 2.41, 2.88, 3.52};

double maxError(const std::vector<double>& found, const std::vector<double>& expected) {
  double worst = 0;
  for (size_t i = 0; i < std::min(found.size(), expected.size()); ++i)
    worst = std::max(worst, std::abs(found[i] - expected[i]));
  return worst;
}

// --- Bands and level ---

AudioFeatures featuresOf(const std::vector<float>& samples) {
  AudioAnalyser analyser(kRate);
  analyser.push(samples);
  return analyser.take();
}

TEST(LiveAudioBands, SinesLandInTheirBands) {
  const AudioFeatures bass = featuresOf(sine(80.0, 1.0, 0.1));
  EXPECT_GT(bass.bass, 0.9f);
  EXPECT_LT(bass.mid, 0.5f);
  EXPECT_LT(bass.high, 0.5f);
  const AudioFeatures mid = featuresOf(sine(1000.0, 1.0, 0.1));
  EXPECT_GT(mid.mid, 0.9f);
  EXPECT_LT(mid.bass, 0.5f);
  EXPECT_LT(mid.high, 0.5f);
  const AudioFeatures high = featuresOf(sine(8000.0, 1.0, 0.1));
  EXPECT_GT(high.high, 0.9f);
  EXPECT_LT(high.bass, 0.5f);
  EXPECT_LT(high.mid, 0.5f);
  std::printf("80 Hz: %.3f %.3f %.3f; 1 kHz: %.3f %.3f %.3f; 8 kHz: %.3f %.3f %.3f\n", bass.bass, bass.mid, bass.high,
              mid.bass, mid.mid, mid.high, high.bass, high.mid, high.high);
  // A full-scale sine reads 0 dBFS in its band and as its level (80 Hz: 1.7 cycles in the window,
  // whose RMS is 0.2 dB off a whole number of cycles').
  for (const AudioFeatures& f : {bass, mid, high}) EXPECT_NEAR(f.level, 1.0f, 0.01f);
  EXPECT_NEAR(mid.mid, 1.0f, 0.01f);
}

TEST(LiveAudioBands, MinusTwentyDecibelsReadsAThirdLess) {
  const double quiet = std::pow(10.0, -20.0 / 20.0);
  for (double hz : {80.0, 1000.0, 8000.0}) {
    const AudioFeatures loud = featuresOf(sine(hz, 1.0, 0.1)), soft = featuresOf(sine(hz, quiet, 0.1));
    const float loudBand = hz < 250 ? loud.bass : hz < 4000 ? loud.mid : loud.high;
    const float softBand = hz < 250 ? soft.bass : hz < 4000 ? soft.mid : soft.high;
    EXPECT_NEAR(loudBand - softBand, 1.0f / 3.0f, 1e-3f) << hz << " Hz";
    EXPECT_NEAR(loud.level - soft.level, 1.0f / 3.0f, 1e-3f) << hz << " Hz";
  }
}

// What ISF's audio inputs draw: the window's samples as pushed, and a full-scale sine on a bin's centre
// reading 1 in that bin, a tenth of it (-20 dB) a third less, far bins near 0.
TEST(LiveAudioSound, TheWindowAndItsSpectrum) {
  AudioAnalyser analyser(kRate);
  const double bin = kRate / double(AudioAnalyser::kWindow);
  const std::vector<float> loud = sine(40 * bin, 1.0, 0.1);
  analyser.push(loud);
  const auto recent = analyser.recentSamples();
  ASSERT_EQ(recent.size(), AudioAnalyser::kWindow);
  const size_t analysed = loud.size() / AudioAnalyser::kHop * AudioAnalyser::kHop;  // whole hops only
  EXPECT_EQ(recent.back(), loud[analysed - 1]);
  std::vector<float> spectrum = analyser.spectrum();
  ASSERT_EQ(spectrum.size(), AudioAnalyser::kWindow / 2);
  EXPECT_NEAR(spectrum[40], 1.0f, 0.01f);
  EXPECT_LT(spectrum[200], 0.05f);
  AudioAnalyser quiet(kRate);
  quiet.push(sine(40 * bin, 0.1, 0.1));
  spectrum = quiet.spectrum();
  EXPECT_NEAR(spectrum[40], 2.0f / 3.0f, 0.01f);
}

TEST(LiveAudioBands, SilenceIsAllZero) {
  AudioAnalyser analyser(kRate);
  const std::vector<float> silence(size_t(5 * kRate), 0.0f);
  for (size_t i = 0; i < silence.size(); i += 800) {
    analyser.push(std::span(silence).subspan(i, std::min<size_t>(800, silence.size() - i)));
    const AudioFeatures f = analyser.take();
    EXPECT_EQ(f.bass + f.mid + f.high + f.level + f.onset + f.beat + f.tempo, 0.0f) << "at sample " << i;
  }
  EXPECT_TRUE(analyser.onsetTimes().empty());
  EXPECT_TRUE(analyser.beatTimes().empty());
}

TEST(LiveAudioBands, BandsAboveNyquistReadZeroAndRatesAreChecked) {
  AudioAnalyser analyser(8000.0);  // Nyquist 4 kHz: no high band at all
  analyser.push(sine(3000.0, 1.0, 0.1, 8000.0));
  const AudioFeatures f = analyser.take();
  EXPECT_GT(f.mid, 0.9f);
  EXPECT_EQ(f.high, 0.0f);
  EXPECT_THROW(AudioAnalyser(0.0), Error);
  EXPECT_THROW(AudioAnalyser(std::nan("")), Error);
  EXPECT_NEAR(AudioAnalyser(kRate).latencySeconds(), 1280.0 / 48000.0, 1e-12);
}

TEST(LiveAudioBands, NonFiniteSamplesAreTakenAsSilence) {
  AudioAnalyser analyser(kRate);
  std::vector<float> samples = sine(1000.0, 1.0, 0.1);
  samples[100] = std::nanf("");
  samples[2000] = INFINITY;
  analyser.push(samples);
  const AudioFeatures f = analyser.take();
  EXPECT_TRUE(std::isfinite(f.mid) && std::isfinite(f.level));
  EXPECT_GT(f.mid, 0.9f);
}

// --- Onsets and beats ---

TEST(LiveAudioOnsets, KicksAreFoundWithinTenMilliseconds) {
  const std::vector<float> track = kickTrack(4.0, kKicks);
  AudioAnalyser analyser(kRate);
  // Frames at 60 Hz: each onset raises the flag in exactly one frame, no later than the analyser's
  // latency after the kick (plus the frame it lands in).
  int flagged = 0;
  double worstLate = 0;
  for (size_t i = 0; i < track.size(); i += 800) {
    analyser.push(std::span(track).subspan(i, 800));
    if (analyser.take().onset == 1.0f) {
      ++flagged;
      const double now = double(i + 800) / kRate, kick = analyser.onsetTimes().back();
      worstLate = std::max(worstLate, now - kick);
    }
  }
  const std::vector<double>& found = analyser.onsetTimes();
  ASSERT_EQ(found.size(), kKicks.size());
  EXPECT_EQ(flagged, int(kKicks.size()));
  const double worst = maxError(found, kKicks);
  std::printf("onsets (hfc): worst error %.2f ms, flagged at most %.1f ms after the kick\n", worst * 1000.0,
              worstLate * 1000.0);
  EXPECT_LT(worst, 0.010);
}

TEST(LiveAudioBeats, SteadyKicksAt120BpmGiveTheTempoAndBeats) {
  std::vector<double> times;
  for (double t = 0.1; t < 20.0; t += 0.5) times.push_back(t);
  const std::vector<float> track = kickTrack(20.0, times);
  AudioAnalyser analyser(kRate);
  AudioFeatures last;
  int beatFrames = 0;
  for (size_t i = 0; i < track.size(); i += 800) {
    analyser.push(std::span(track).subspan(i, std::min<size_t>(800, track.size() - i)));
    last = analyser.take();
    beatFrames += last.beat == 1.0f;
  }
  const std::vector<double>& beats = analyser.beatTimes();
  // Each beat's distance to the nearest kick, once the tracker has settled. Beats are predicted from
  // a period of whole hops and put right every 2.7 s, so they drift a little between (measured:
  // 21 ms at worst, early).
  double worst = 0;
  for (double b : beats) {
    const double phase = std::remainder(b - 0.1, 0.5);
    if (b > 10.0) worst = std::max(worst, std::abs(phase));
  }
  std::printf("tempo %.2f BPM, %zu beats (first at %.2f s), %d frames flagged, worst beat after 10 s %.1f ms\n",
              last.tempo, beats.size(), beats.empty() ? 0.0 : beats.front(), beatFrames, worst * 1000.0);
  EXPECT_NEAR(last.tempo, 120.0f, 2.0f);
  ASSERT_GT(beats.size(), 20u);
  // The beat pulse: the onsets until the tempo is known, aubio's beats after; one pulse a kick.
  EXPECT_EQ(beatFrames, int(times.size()));
  EXPECT_LT(worst, 0.030);
}

TEST(LiveAudioAnalysis, BlockSizesGiveIdenticalFeaturesAndTimes) {
  const std::vector<float> track = kickTrack(4.0, kKicks);
  constexpr size_t kFrame = 800;
  struct Run {
    std::vector<AudioFeatures> features;
    std::vector<double> onsets, beats;
  };
  const auto run = [&](size_t block) {
    AudioAnalyser analyser(kRate);
    Run result;
    for (size_t frame = 0; frame < track.size(); frame += kFrame) {
      const size_t end = std::min(frame + kFrame, track.size());
      for (size_t i = frame; i < end; i += block)
        analyser.push(std::span(track).subspan(i, std::min(block, end - i)));
      result.features.push_back(analyser.take());
    }
    result.onsets = analyser.onsetTimes();
    result.beats = analyser.beatTimes();
    return result;
  };
  const Run reference = run(256);
  for (size_t block : {size_t(1), size_t(37), size_t(4096)}) {
    const Run other = run(block);
    ASSERT_EQ(other.features.size(), reference.features.size());
    for (size_t i = 0; i < reference.features.size(); ++i) {
      const AudioFeatures &a = reference.features[i], &b = other.features[i];
      EXPECT_TRUE(a.bass == b.bass && a.mid == b.mid && a.high == b.high && a.level == b.level &&
                  a.onset == b.onset && a.beat == b.beat && a.tempo == b.tempo)
          << "block " << block << ", frame " << i;
    }
    EXPECT_EQ(other.onsets, reference.onsets) << "block " << block;
    EXPECT_EQ(other.beats, reference.beats) << "block " << block;
  }
  EXPECT_EQ(reference.onsets.size(), kKicks.size());
}

// --- Sound files ---

class LiveAudioClip : public test::TempFolderTest {};

std::vector<float> stereoOf(const std::vector<float>& left, const std::vector<float>& right) {
  std::vector<float> out(left.size() * 2);
  for (size_t i = 0; i < left.size(); ++i) {
    out[2 * i] = left[i];
    out[2 * i + 1] = right[i];
  }
  return out;
}

void writeMono(const std::filesystem::path& path, const std::vector<float>& samples, int rate) {
  SF_INFO info{};
  info.samplerate = rate;
  info.channels = 1;
  info.format = SF_FORMAT_WAV | SF_FORMAT_FLOAT;
  SNDFILE* file = sf_open(path.c_str(), SFM_WRITE, &info);
  ASSERT_NE(file, nullptr) << sf_strerror(nullptr);
  ASSERT_EQ(sf_writef_float(file, samples.data(), sf_count_t(samples.size())), sf_count_t(samples.size()));
  sf_close(file);
}

TEST_F(LiveAudioClip, WavRoundTripsInBothFormats) {
  const std::vector<float> stereo = stereoOf(sine(440.0, 0.5, 0.5), sine(660.0, 0.25, 0.5));
  for (audio::WavFormat format : {audio::WavFormat::Pcm16, audio::WavFormat::Float32}) {
    const auto path = folder_ / "round.wav";
    audio::writeWav(path, stereo, format);
    const AudioClip clip = readAudioFile(path);
    EXPECT_EQ(clip.sampleRate, 48000.0);
    EXPECT_EQ(clip.channels, 2);
    ASSERT_EQ(clip.frames(), stereo.size() / 2);
    EXPECT_DOUBLE_EQ(clip.seconds(), 0.5);
    const float tolerance = format == audio::WavFormat::Pcm16 ? 1.0f / 32768.0f : 0.0f;
    float worst = 0;
    for (size_t i = 0; i < stereo.size(); ++i) worst = std::max(worst, std::abs(clip.samples[i] - stereo[i]));
    EXPECT_LE(worst, tolerance);
    const std::vector<float> mono = monoMix(clip);
    EXPECT_NEAR(mono[100], (clip.samples[200] + clip.samples[201]) / 2.0f, 1e-7f);
  }
}

TEST_F(LiveAudioClip, ResamplesTo48kKeepingTimeAndPitch) {
  // 1 kHz at 44.1 kHz, mono: taken from 0.5 s for 1 s it is the same sine on the 48 kHz clock.
  const auto path = folder_ / "44k.wav";
  writeMono(path, sine(1000.0, 0.5, 2.0, 44100.0), 44100);
  const AudioClip clip = readAudioFile(path);
  EXPECT_EQ(clip.sampleRate, 44100.0);
  const std::vector<float> out = stereo48k(clip, 0.5, 1.0);
  ASSERT_EQ(out.size(), 2u * 48000u);
  double worst = 0;
  for (size_t j = 0; j < 48000; ++j) {
    const double expected = 0.5 * std::sin(2.0 * kPi * 1000.0 * (0.5 + double(j) / 48000.0));
    worst = std::max(worst, std::abs(out[2 * j] - expected));
    ASSERT_EQ(out[2 * j], out[2 * j + 1]);
  }
  std::printf("44.1 kHz -> 48 kHz: worst error %.2g\n", worst);
  EXPECT_LT(worst, 1e-3);
  // Odd lengths round to the nearest frame; past the end is silence, or the start again when looping.
  EXPECT_EQ(stereo48k(clip, 0.0, 0.0100104).size(), 2u * 480u);
  const std::vector<float> tail = stereo48k(clip, 1.9, 0.2);
  for (size_t j = 4900; j < 9600; ++j) EXPECT_EQ(tail[2 * j], 0.0f) << j;
  const std::vector<float> looped = stereo48k(clip, 1.9, 0.2, true);
  const std::vector<float> head = stereo48k(clip, 0.0, 0.1);
  for (size_t j = 5000; j < 9000; j += 7) EXPECT_NEAR(looped[2 * j], head[2 * (j - 4800)], 2e-3f) << j;
}

// A film's music is resampled a stretch at a time as the film goes: the stretches, however ragged, are
// sample for sample the whole span resampled at once, at 44.1 kHz (the filter's state carried across),
// downsampled from 96 kHz, and at 48 kHz looped.
TEST_F(LiveAudioClip, StretchesEqualTheWholeSpan) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> noise(-0.8f, 0.8f);
  for (const double rate : {44100.0, 96000.0, 48000.0}) {
    AudioClip clip;
    clip.sampleRate = rate;
    clip.channels = 2;
    clip.samples.resize(size_t(rate * 1.5) * 2);
    for (float& s : clip.samples) s = noise(random);
    const bool loop = rate == 48000.0;
    const std::vector<float> whole = stereo48k(clip, 0.2, 2.0, loop);
    Stereo48kStream stream(clip, 0.2, loop);
    std::vector<float> stretches(whole.size());
    const size_t ragged[] = {1, 700, 4096, 10007, 3};
    for (size_t done = 0, i = 0; done < whole.size() / 2; ++i) {
      const size_t frames = std::min(ragged[i % 5], whole.size() / 2 - done);
      stream.next(stretches.data() + 2 * done, frames);
      done += frames;
    }
    EXPECT_EQ(stretches, whole) << rate << " Hz";
    EXPECT_GT(*std::max_element(whole.begin(), whole.begin() + 48000), 0.5f);  // the clip, not silence
  }
}

TEST_F(LiveAudioClip, At48kIsTheClipItself) {
  const std::vector<float> stereo = stereoOf(sine(440.0, 0.5, 1.0), sine(3000.0, 0.3, 1.0));
  const auto path = folder_ / "48k.wav";
  audio::writeWav(path, stereo, audio::WavFormat::Float32);
  const AudioClip clip = readAudioFile(path);
  const std::vector<float> out = stereo48k(clip, 0.25, 0.5);
  ASSERT_EQ(out.size(), 48000u);
  for (size_t i = 0; i < out.size(); ++i) ASSERT_NEAR(out[i], stereo[12000 * 2 + i], 1e-4f) << i;
  // Looped past the end: the start again.
  const std::vector<float> looped = stereo48k(clip, 0.9, 0.2, true);
  EXPECT_EQ(looped[2 * 4800], stereo[0]);
  EXPECT_EQ(looped[2 * 4800 + 1], stereo[1]);
  EXPECT_THROW(stereo48k(clip, 0.0, -1.0), Error);
  EXPECT_THROW(stereo48k(clip, NAN, 1.0), Error);
}

TEST_F(LiveAudioClip, MissingAndCorruptFilesAreRefusedByName) {
  const auto missing = folder_ / "missing.wav";
  try {
    readAudioFile(missing);
    FAIL() << "read a missing file";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
    std::printf("%s\n", e.what());
  }
  const auto corrupt = folder_ / "corrupt.wav";
  std::ofstream(corrupt) << "RIFF this is not a sound file at all, just some words in a row";
  try {
    readAudioFile(corrupt);
    FAIL() << "read a corrupt file";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(corrupt.string()), std::string::npos) << e.what();
    std::printf("%s\n", e.what());
  }
  const auto empty = folder_ / "empty.wav";
  audio::writeWav(empty, {});
  EXPECT_THROW(readAudioFile(empty), Error);
}

// --- A file as live input ---

AudioClip clipOf(std::vector<float> mono) {
  AudioClip clip;
  clip.sampleRate = kRate;
  clip.channels = 1;
  clip.samples = std::move(mono);
  return clip;
}

TEST(LiveAudioFileInput, StepsOfASixtiethAndAThirtiethAgree) {
  AudioFileInput fine(clipOf(kickTrack(4.0, kKicks)), false), coarse(clipOf(kickTrack(4.0, kKicks)), false);
  double tFine = 0, tCoarse = 0;
  float pending = 0;  // the fine run's onset in the frame between two coarse ones
  for (int frame = 1; frame <= 240; ++frame) {
    tFine += 1.0 / 60.0;
    const AudioFeatures f = fine.at(tFine);
    if (frame % 2 == 1) {
      pending = f.onset;
      continue;
    }
    tCoarse += 1.0 / 30.0;
    const AudioFeatures c = coarse.at(tCoarse);
    EXPECT_TRUE(f.bass == c.bass && f.mid == c.mid && f.high == c.high && f.level == c.level && f.tempo == c.tempo)
        << "at frame " << frame;
    EXPECT_EQ(std::max(pending, f.onset), c.onset) << "at frame " << frame;
  }
  EXPECT_EQ(fine.analyser().onsetTimes(), coarse.analyser().onsetTimes());
  EXPECT_EQ(fine.analyser().onsetTimes().size(), kKicks.size());
}

TEST(LiveAudioFileInput, LoopsWrapAndTheEndIsSilence) {
  AudioFileInput looped(clipOf(kickTrack(1.0, {0.2})), true), once(clipOf(kickTrack(1.0, {0.2})), false);
  AudioFeatures last;
  for (int frame = 1; frame <= 210; ++frame) {
    looped.at(frame / 60.0);
    last = once.at(frame / 60.0);
  }
  const std::vector<double>& onsets = looped.analyser().onsetTimes();
  ASSERT_EQ(onsets.size(), 4u);
  for (size_t i = 0; i < onsets.size(); ++i) EXPECT_NEAR(onsets[i], 0.2 + double(i), 0.01);
  EXPECT_EQ(once.analyser().onsetTimes().size(), 1u);
  EXPECT_EQ(last.level, 0.0f);
  // Time does not go back.
  EXPECT_EQ(once.at(1.0).level, 0.0f);
  EXPECT_EQ(once.analyser().streamPosition(), uint64_t(3.5 * kRate));
}

TEST(LiveAudioFileInput, StartsAtItsStartTimeAndCatchesUpAfterAJump) {
  AudioFileInput input(clipOf(kickTrack(1.0, {0.2})), true, 10.0);
  EXPECT_EQ(input.at(5.0).level, 0.0f);
  EXPECT_EQ(input.analyser().streamPosition(), 0u);
  input.at(10.5);
  ASSERT_EQ(input.analyser().onsetTimes().size(), 1u);
  EXPECT_NEAR(input.analyser().onsetTimes()[0], 0.2, 0.01);
  // An hour later: only the last 30 s are analysed, their times still from file time 0.
  input.at(3610.5);
  const std::vector<double>& onsets = input.analyser().onsetTimes();
  ASSERT_GE(onsets.size(), 29u);
  EXPECT_NEAR(onsets.back(), 3600.2, 0.01);
  EXPECT_EQ(input.analyser().streamPosition(), uint64_t(3600.5 * kRate));
}

TEST_F(LiveAudioClip, FileInputReadsItsFile) {
  const auto path = folder_ / "kicks.wav";
  const std::vector<float> mono = kickTrack(4.0, kKicks);
  audio::writeWav(path, stereoOf(mono, mono), audio::WavFormat::Float32);
  AudioFileInput input(path, false);
  input.at(4.0);
  EXPECT_EQ(input.clip().channels, 2);
  EXPECT_LT(maxError(input.analyser().onsetTimes(), kKicks), 0.010);
  EXPECT_THROW(AudioFileInput(folder_ / "nothing.flac", false), Error);
}

// --- Capture ---

TEST(LiveAudioCapture, WithoutADeviceSaysSoOnceAndGivesZeros) {
  testing::internal::CaptureStderr();
  {
    AudioCapture capture(AudioCapture::Options{.useDevice = false});
    EXPECT_FALSE(capture.active());
    EXPECT_EQ(capture.status(), "no audio input (not asked to open one)");
    const AudioFeatures f = capture.take();
    EXPECT_EQ(f.bass + f.mid + f.high + f.level + f.onset + f.beat + f.tempo, 0.0f);
    EXPECT_EQ(capture.bufferMs(), 0.0);
    EXPECT_EQ(capture.analyser(), nullptr);
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "vitrine: no audio input (not asked to open one): live audio off\n");

  // The default device: whatever the sound system has to say, one line reaches stderr when none
  // opens, nothing when one does.
  testing::internal::CaptureStderr();
  std::unique_ptr<AudioCapture> capture;
  EXPECT_NO_THROW(capture = std::make_unique<AudioCapture>(AudioCapture::Options{}));
  capture->take();
  const bool active = capture->active();
  const std::string status = capture->status();
  capture.reset();
  const std::string said = testing::internal::GetCapturedStderr();
  std::printf("default input: %s (devices: %zu)\n", status.c_str(), AudioCapture::inputDevices().size());
  if (!active) {
    EXPECT_EQ(said, "vitrine: " + status + ": live audio off\n");
  } else {
    EXPECT_EQ(said, "");
  }
}

TEST(LiveAudioCapture, RingKeepsOrderAndDropsWhatDoesNotFit) {
  FloatRing ring(6);  // rounded up to 8
  EXPECT_EQ(ring.capacity(), 8u);
  std::vector<float> in = {1, 2, 3, 4, 5}, out(8);
  EXPECT_EQ(ring.push(in), 5u);
  EXPECT_EQ(ring.pop(std::span(out).first(3)), 3u);
  EXPECT_EQ(ring.push(in), 5u);  // wraps around the end
  EXPECT_EQ(ring.push(in), 1u);  // full: four dropped
  EXPECT_EQ(ring.dropped(), 4u);
  EXPECT_EQ(ring.pop(out), 8u);
  EXPECT_EQ(out, (std::vector<float>{4, 5, 1, 2, 3, 4, 5, 1}));
  EXPECT_EQ(ring.pop(out), 0u);
}

}  // namespace
}  // namespace vitrine::live
