// The sound: bell, drone and reverb measured from rendered samples, the partitioned convolution
// against the direct sum, the wet envelope, the limiter, sample-exact commands, the lock-free
// queue, the WAV writer and the silent fallback without a device.

// This file replaces the global operator new and delete (below) with malloc and free; GCC sees
// both ends of vector allocations inlined here and takes the pair for a mismatch.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <kissfft/kiss_fftr.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <new>
#include <numbers>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "audio/audio_sink.h"
#include "audio/engine.h"
#include "audio/sound_tap.h"
#include "audio/spsc_queue.h"
#include "audio/synth.h"
#include "audio/wav.h"
#include "core/error.h"
#include "support/temp_folder.h"
#include "support/files.h"
#include "support/trials.h"

// Counts heap allocations, so a test can show that rendering makes none. Replacing the global
// operators is per program; every other test just allocates through malloc as before.
namespace {
std::atomic<size_t> gAllocations{0};
}
void* operator new(size_t bytes) {
  ++gAllocations;
  if (void* p = std::malloc(bytes ? bytes : 1)) return p;
  throw std::bad_alloc();
}
// The nothrow form too (std::stable_sort's buffer): else it comes from the runtime's own operator new
// and is released by the free() below, which AddressSanitizer reports as alloc-dealloc-mismatch.
void* operator new(size_t bytes, const std::nothrow_t&) noexcept {
  ++gAllocations;
  return std::malloc(bytes ? bytes : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }

namespace vitrine::audio {
namespace {

constexpr double kPi = std::numbers::pi;

// Amplitude of the component at `hz`: a Hann-windowed DFT evaluated at exactly that frequency,
// scaled so a steady sine of amplitude A reads A.
double amplitudeAt(const std::vector<float>& x, double hz, size_t first = 0, size_t count = 0) {
  if (count == 0) count = x.size() - first;
  std::complex<double> sum = 0;
  double weights = 0;
  const double w = 2 * kPi * hz / kSampleRate;
  for (size_t n = 0; n < count; ++n) {
    const double hann = 0.5 - 0.5 * std::cos(2 * kPi * double(n) / double(count));
    sum += hann * double(x[first + n]) * std::polar(1.0, -w * double(n));
    weights += hann;
  }
  return 2 * std::abs(sum) / weights;
}

// Hann-windowed magnitude spectrum through KissFFT's real FFT, zero-padded to at least four
// times the signal so a peak can be located to a small fraction of the window's resolution.
struct Spectrum {
  std::vector<double> magnitude;
  double binHz;
};

Spectrum spectrum(const std::vector<float>& x) {
  size_t n = 2;
  while (n < 4 * x.size()) n *= 2;
  std::vector<float> windowed(n, 0.0f);
  for (size_t i = 0; i < x.size(); ++i)
    windowed[i] = float(x[i] * (0.5 - 0.5 * std::cos(2 * kPi * double(i) / double(x.size()))));
  std::vector<kiss_fft_cpx> bins(n / 2 + 1);
  kiss_fftr_cfg plan = kiss_fftr_alloc(int(n), 0, nullptr, nullptr);
  kiss_fftr(plan, windowed.data(), bins.data());
  kiss_fftr_free(plan);
  Spectrum s{{}, double(kSampleRate) / double(n)};
  for (const auto& b : bins) s.magnitude.push_back(std::hypot(double(b.r), double(b.i)));
  return s;
}

// The strongest peak between lo and hi, refined by a parabola through the log magnitudes of the
// top bin and its neighbours (exact for a Gaussian, close for a Hann window's main lobe).
double peakHz(const Spectrum& s, double lo, double hi) {
  size_t best = size_t(lo / s.binHz);
  for (size_t k = best; k <= size_t(hi / s.binHz); ++k)
    if (s.magnitude[k] > s.magnitude[best]) best = k;
  const double a = std::log(s.magnitude[best - 1]), b = std::log(s.magnitude[best]),
               c = std::log(s.magnitude[best + 1]);
  return (double(best) + 0.5 * (a - c) / (a - 2 * b + c)) * s.binHz;
}

std::vector<float> renderVoice(float hz, float level, std::span<const Partial> partials, double seconds) {
  BellVoice voice;
  voice.start(hz, level, partials, 0);
  std::vector<float> out(size_t(toSamples(seconds)));
  for (float& s : out) s = voice.next();
  return out;
}

// Renders a synth and returns the left channel, checking that the right one is the same.
std::vector<float> renderLeft(Synth& synth, double seconds) {
  std::vector<float> stereo(size_t(toSamples(seconds)) * 2);
  synth.render(stereo.data(), stereo.size() / 2);
  std::vector<float> left(stereo.size() / 2);
  for (size_t i = 0; i < left.size(); ++i) {
    EXPECT_EQ(stereo[2 * i], stereo[2 * i + 1]) << "frame " << i;
    left[i] = stereo[2 * i];
  }
  return left;
}

float peak(const std::vector<float>& x) {
  float p = 0;
  for (float s : x) p = std::max(p, std::abs(s));
  return p;
}

// --- Bell ---

TEST(AudioBell, PartialsAtTheirFrequenciesAndRatios) {
  for (const float hz : {kE4, kB4, kE5}) {
    const auto bell = renderVoice(hz, 1.0f, kBellPartials, kBellAttack + kBellDecay);
    const Spectrum s = spectrum(bell);
    const double fundamental = amplitudeAt(bell, hz);
    for (const Partial& p : kBellPartials) {
      const double expected = hz * p.ratio;
      const double measured = peakHz(s, expected - 20, expected + 20);
      EXPECT_NEAR(measured, expected, 0.1) << hz << " Hz bell, partial x" << p.ratio;
      const double ratio = amplitudeAt(bell, expected) / fundamental;
      EXPECT_NEAR(ratio, p.amplitude, 0.002) << hz << " Hz bell, partial x" << p.ratio;
      std::printf("bell %.2f Hz: partial x%g at %.3f Hz, amplitude ratio %.4f\n", hz, p.ratio, measured, ratio);
    }
  }
}

TEST(AudioBell, ClimaxBellsAddTheSixthHarmonic) {
  const auto bell = renderVoice(330.0f, 1.0f, kClimaxPartials, 1.0);
  EXPECT_NEAR(peakHz(spectrum(bell), 1960, 2000), 1980.0, 0.1);
  EXPECT_NEAR(amplitudeAt(bell, 1980) / amplitudeAt(bell, 330), 0.08, 0.002);
}

TEST(AudioBell, AttackIsThreeMillisecondsLinear) {
  // One partial at 1 kHz: where the sine is well away from zero, sample / sine is the envelope.
  const float hz = 1000.0f;
  const auto bell = renderVoice(hz, 1.0f, std::array<Partial, 1>{{{1, 1.0f}}}, 0.01);
  EXPECT_EQ(bell[0], 0.0f) << "a bell starts from silence";
  // Least-squares slope of the envelope through the origin over the rise: 1 / slope is its length.
  double xy = 0, xx = 0, worst = 0;
  for (size_t n = 1; n < 144; ++n) {
    const double sine = std::sin(2 * kPi * hz * double(n) / kSampleRate);
    if (std::abs(sine) < 0.5) continue;
    const double envelope = bell[n] / sine;
    xy += double(n) * envelope;
    xx += double(n) * n;
    worst = std::max(worst, std::abs(envelope - bellEnvelope(double(n) / kSampleRate)));
  }
  const double attackSamples = xx / xy;
  std::printf("bell attack: %.2f samples = %.4f ms\n", attackSamples, attackSamples * 1000 / kSampleRate);
  EXPECT_NEAR(attackSamples, 144.0, 0.05);
  EXPECT_LT(worst, 1e-5);
  EXPECT_DOUBLE_EQ(bellEnvelope(kBellAttack), 1.0);
  EXPECT_LT(bellEnvelope(kBellAttack + 0.001), 1.0) << "the decay starts right after the attack";
}

TEST(AudioBell, DecayTimeConstantGivesMinusSixtyDecibelsAtOnePointEightSeconds) {
  const auto bell = renderVoice(kE4, kBellLevel, kBellPartials, 2.0);
  // The same window at two times sees the same shape scaled by e^(-dt/tau).
  const size_t window = 2400;  // 50 ms
  const double t1 = 0.1, t2 = 1.1;
  const double a1 = amplitudeAt(bell, kE4, size_t(toSamples(t1)), window);
  const double a2 = amplitudeAt(bell, kE4, size_t(toSamples(t2)), window);
  const double tau = (t2 - t1) / std::log(a1 / a2);
  std::printf("bell decay: tau %.5f s (expected %.5f), -60 dB after %.4f s\n", tau, kBellTau, tau * std::log(1000.0));
  EXPECT_NEAR(tau, 1.8 / std::log(1000.0), 1e-4);
  EXPECT_NEAR(tau * std::log(1000.0), 1.8, 1e-3);
  // Then it ends: silence from 1.8 s after the attack.
  const size_t end = size_t(toSamples(kBellAttack + kBellDecay));
  EXPECT_NE(bell[end - 100], 0.0f);
  for (size_t n = end; n < bell.size(); ++n) ASSERT_EQ(bell[n], 0.0f) << "sample " << n;
}

// --- Drone ---

TEST(AudioDrone, RootAndDetunedOctaveUnderTheLowPass) {
  Drone drone;
  drone.setOn(true);
  for (int n = 0; n < kSampleRate; ++n) drone.next();  // fade-in and filter settled
  std::vector<float> hum(size_t(10 * kSampleRate));
  for (float& s : hum) s = drone.next();

  const Spectrum s = spectrum(hum);
  const double root = peakHz(s, 50, 60), octave = peakHz(s, 105, 115);
  const Biquad filter = Biquad::lowPass(kDroneCutoffHz, 0.707);
  const double ratio = amplitudeAt(hum, kDroneOctaveHz) / amplitudeAt(hum, kDroneRootHz);
  std::printf("drone: %.3f Hz and %.3f Hz, octave/root %.4f, peak %.4f\n", root, octave, ratio, peak(hum));
  EXPECT_NEAR(root, 55.0, 0.02);
  EXPECT_NEAR(octave, 110.3, 0.02) << "detuned from the true octave (110 Hz)";
  EXPECT_NEAR(ratio, 0.5 * filter.magnitudeAt(110.3) / filter.magnitudeAt(55.0), 0.002);
  EXPECT_NEAR(peak(hum), 0.12, 0.005);

  // Everything above 200 Hz together is far below the 55 Hz component.
  double above = 0;
  for (size_t k = size_t(200 / s.binHz); k < s.magnitude.size(); ++k) above += s.magnitude[k] * s.magnitude[k];
  const double rootPower = std::pow(s.magnitude[size_t(std::lround(55.0 / s.binHz))], 2);
  std::printf("drone: power above 200 Hz %.1f dB below the 55 Hz peak\n", 10 * std::log10(rootPower / above));
  EXPECT_LT(above, rootPower * 1e-6);
}

TEST(AudioDrone, LowPassFallsTwelveDecibelsPerOctaveAbove180Hz) {
  // Steady sines through the filter: measured gain matches |H| and the Butterworth shape.
  for (const double hz : {55.0, 180.0, 720.0, 2880.0}) {
    Biquad filter = Biquad::lowPass(180.0, 0.707);
    std::vector<float> out(static_cast<size_t>(kSampleRate));
    for (size_t n = 0; n < out.size(); ++n)
      out[n] = filter.process(float(std::sin(2 * kPi * hz * double(n) / kSampleRate)));
    const double gain = amplitudeAt(out, hz, out.size() / 2);
    const double butterworth = 1.0 / std::sqrt(1.0 + std::pow(hz / 180.0, 4));
    std::printf("low-pass at %.0f Hz: %.2f dB\n", hz, 20 * std::log10(gain));
    EXPECT_NEAR(gain, filter.magnitudeAt(hz), 1e-3 * filter.magnitudeAt(hz) + 1e-6);
    EXPECT_NEAR(20 * std::log10(gain), 20 * std::log10(butterworth), 0.3) << hz << " Hz";
  }
}

// --- Plate reverb ---

TEST(AudioReverb, ImpulseFollowsItsEnvelopeAndItsSeed) {
  const auto h = plateImpulse(kPlateSeed);
  ASSERT_EQ(h.size(), 14400u) << "300 ms";
  double energy = 0, expectedTotal = 0;
  for (size_t i = 0; i < h.size(); ++i) {
    energy += double(h[i]) * h[i];
    expectedTotal += std::pow(1.0 - double(i) / double(h.size()), 2 * kPlateShape);
  }
  EXPECT_NEAR(energy, 1.0, 1e-5) << "unit energy";
  // Energy per 30 ms window against what the squared envelope puts there.
  const size_t window = 1440;
  double worst = 0;
  for (size_t first = 0; first < h.size(); first += window) {
    double measured = 0, expected = 0;
    for (size_t i = first; i < first + window; ++i) {
      measured += double(h[i]) * h[i];
      expected += std::pow(1.0 - double(i) / double(h.size()), 2 * kPlateShape) / expectedTotal;
    }
    worst = std::max(worst, std::abs(measured / expected - 1));
    EXPECT_NEAR(measured / expected, 1.0, 0.15) << "window at " << first / 48 << " ms";
  }
  std::printf("plate impulse: worst 30 ms window energy %.1f%% off the envelope\n", worst * 100);

  EXPECT_EQ(plateImpulse(7), plateImpulse(7));
  EXPECT_NE(plateImpulse(7), plateImpulse(8));
}

TEST(AudioReverb, PartitionedConvolutionEqualsDirect) {
  std::mt19937 random(42);
  std::uniform_real_distribution<float> uniform(-1.0f, 1.0f);
  std::vector<float> x(test::trials(20000));
  for (float& s : x) s = uniform(random);
  // The plate with two block sizes, and a short response that ends mid-partition.
  std::vector<float> odd(1000);
  for (float& s : odd) s = uniform(random) * 0.05f;
  const std::vector<float> plate = plateImpulse(kPlateSeed);
  struct Case {
    const std::vector<float>* impulse;
    size_t block;
  };
  for (const auto& [impulse, block] : {Case{&plate, 256}, Case{&plate, 512}, Case{&odd, 256}}) {
    PartitionedConvolver convolver(*impulse, block);
    EXPECT_EQ(convolver.partitions(), (impulse->size() + block - 1) / block);
    double worst = 0;
    for (size_t n = 0; n < x.size() + convolver.latency(); ++n) {
      const float y = convolver.process(n < x.size() ? x[n] : 0.0f);
      if (n < convolver.latency()) continue;
      const size_t m = n - convolver.latency();
      double direct = 0;
      for (size_t k = 0; k < impulse->size() && k <= m; ++k) direct += double((*impulse)[k]) * x[m - k];
      worst = std::max(worst, std::abs(double(y) - direct));
    }
    std::printf("convolution: %zu taps, block %zu: max error %.2e\n", impulse->size(), block, worst);
    EXPECT_LT(worst, 1e-4);
  }
}

TEST(AudioReverb, WetOpensToClimaxAmountHoldsSixSecondsAndCloses) {
  WetEnvelope wet;
  for (int n = 0; n < 1000; ++n) ASSERT_EQ(wet.next(), 0.0f) << "dry until a climax";
  wet.climax();
  std::vector<float> v(size_t(toSamples(7.0)));
  for (float& s : v) s = wet.next();
  const size_t ramp = size_t(toSamples(kWetRamp)), hold = size_t(toSamples(kWetHold));
  EXPECT_GT(v[0], 0.0f);
  EXPECT_LT(v[ramp / 2], kClimaxWet);
  for (size_t n = ramp - 1; n < ramp + hold; ++n) ASSERT_EQ(v[n], kClimaxWet) << "open at sample " << n;
  EXPECT_LT(v[ramp + hold], kClimaxWet) << "closing from 6.3 s";
  EXPECT_EQ(v[2 * ramp + hold - 1], 0.0f) << "closed by 6.6 s";
  // Glides, never jumps: no step bigger than one ramp step.
  float biggest = 0;
  for (size_t n = 1; n < v.size(); ++n) biggest = std::max(biggest, std::abs(v[n] - v[n - 1]));
  EXPECT_LE(biggest, kClimaxWet / float(ramp) * 1.001f);
  std::printf("wet: 0.28 from %.4f s to %.4f s after the climax, closed at %.4f s\n", double(ramp) / kSampleRate,
              double(ramp + hold) / kSampleRate, double(2 * ramp + hold) / kSampleRate);

  // An override fixes the amount; clearing it hands back to the automation (closed by now).
  wet.setOverride(1.0f);
  for (size_t n = 0; n < ramp; ++n) wet.next();
  EXPECT_EQ(wet.value(), 1.0f);
  wet.climax();
  for (size_t n = 0; n < ramp; ++n) wet.next();
  EXPECT_EQ(wet.value(), 1.0f) << "a climax leaves an override alone";
  wet.setOverride(std::nullopt);
  for (size_t n = 0; n < ramp; ++n) wet.next();
  EXPECT_EQ(wet.value(), kClimaxWet) << "back to the automation, still inside the climax's hold";
}

// --- The mix ---

TEST(AudioMix, ClimaxChordAloneStaysBelowFullScale) {
  std::vector<float> chord(size_t(toSamples(2.0)), 0.0f);
  for (const float hz : kClimaxChordHz) {
    const auto bell = renderVoice(hz, kClimaxLevel, kClimaxPartials, 2.0);
    for (size_t n = 0; n < chord.size(); ++n) chord[n] += bell[n];
  }
  std::printf("climax chord: peak %.4f\n", peak(chord));
  EXPECT_LT(peak(chord), 1.0f);
}

TEST(AudioMix, EverythingAtOnceNeverClips) {
  for (const bool fullWet : {false, true}) {
    Synth synth;
    synth.post({Command::Kind::Drone, 0, 1});
    // Drone settled, then three bells, the chord and (once) the reverb forced fully wet together.
    const int64_t at = toSamples(1.0);
    for (const float hz : {kE4, kB4, kE5}) synth.post({Command::Kind::Bell, at, hz});
    synth.post({Command::Kind::Climax, at, 0});
    if (fullWet) synth.post({Command::Kind::ReverbWet, at, 1.0f});
    const auto mix = renderLeft(synth, 8.0);
    std::printf("everything at once (%s wet): peak %.4f\n", fullWet ? "full" : "climax", peak(mix));
    EXPECT_LE(peak(mix), 1.0f);
    EXPECT_GT(peak(mix), 0.3f) << "and it is not silent";
  }
  // The limiter holds any input to its ceiling (within float rounding), even what is not a number.
  Limiter limiter;
  for (const float x : {0.5f, 3.0f, -40.0f, 1e30f, NAN, INFINITY, 0.99f})
    EXPECT_LE(std::abs(limiter.process(x)), 0.98f * (1 + 1e-6f)) << x;
}

TEST(AudioMix, VolumeAndMuteGlide) {
  Synth synth;
  synth.post({Command::Kind::Drone, 0, 1});
  synth.post({Command::Kind::Mute, toSamples(1.0), 1});
  const auto out = renderLeft(synth, 1.1);
  const size_t muted = size_t(toSamples(1.0 + kLevelGlide));
  for (size_t n = muted; n < out.size(); ++n) ASSERT_EQ(out[n], 0.0f) << "muted at sample " << n;
  EXPECT_NE(out[size_t(toSamples(1.0 + kLevelGlide / 2))], 0.0f) << "a glide, not a cut";
}

// --- Engine: timing, voices, allocation ---

TEST(AudioEngine, CommandsApplyAtTheirExactSample) {
  for (const double start : {0.0, 10.0}) {
    OfflineAudio offline(start);
    offline.bell(start + 0.5, kE4);
    const auto stereo = offline.render(1.0);
    ASSERT_EQ(stereo.size(), 2u * 48000u);
    size_t first = 0;
    while (first < stereo.size() / 2 && stereo[2 * first] == 0.0f) ++first;
    // The attack starts from zero at sample 24000, so 24001 is the first sample that sounds.
    EXPECT_EQ(first, 24001u) << "run from " << start << " s";
  }
  // Exactly round(T x 48000) frames.
  EXPECT_EQ(OfflineAudio().render(0.1).size(), 2u * 4800u);
  EXPECT_EQ(OfflineAudio().render(1.00001).size(), 2u * 48000u);
  EXPECT_THROW(OfflineAudio().render(-1.0), Error);
  EXPECT_THROW(OfflineAudio().render(NAN), Error);
}

TEST(AudioEngine, BlockSizesDoNotChangeTheSound) {
  // The same commands rendered in one go (offline) and in ragged device-sized blocks.
  OfflineAudio offline;
  offline.drone(0.0, true);
  offline.bell(0.25, kE4);
  offline.climax(0.5004, kClimaxWet);
  offline.bell(0.7, kE5);
  const auto expected = offline.render(1.5);

  Synth synth;
  synth.post({Command::Kind::Drone, 0, 1});
  synth.post({Command::Kind::Bell, sampleTime(0.25), kE4});
  synth.post({Command::Kind::Climax, sampleTime(0.5004), kClimaxWet});
  synth.post({Command::Kind::Bell, sampleTime(0.7), kE5});
  std::vector<float> got(expected.size());
  size_t done = 0;
  const size_t blocks[] = {1, 333, 512, 4097};
  for (size_t i = 0; done < got.size() / 2; ++i) {
    const size_t frames = std::min(blocks[i % 4], got.size() / 2 - done);
    synth.render(got.data() + 2 * done, frames);
    done += frames;
  }
  EXPECT_EQ(got, expected);
}

TEST(AudioEngine, FullPoolStealsTheOldestVoice) {
  Synth synth;
  for (int i = 0; i <= int(Synth::kVoices); ++i) synth.post({Command::Kind::Bell, i * 100, 200.0f + 10.0f * i});
  std::vector<float> out(2 * 100 * (Synth::kVoices + 1));
  synth.render(out.data(), out.size() / 2);
  EXPECT_EQ(synth.ringing(), Synth::kVoices);
}

// A run's sound as a film writes it: stretches rendered while the run still posts commands, each a
// little behind the run's time (as record's film does), give exactly the samples a whole render gives
// once the run is over; the stretches' ends fall anywhere, also inside a stretch of commands.
TEST(AudioEngine, StretchesRenderedAsTheRunGoesEqualTheWholeRender) {
  const double start = 3.7;  // a run from --time 3.7: commands before it apply at its first sample
  OfflineAudio run(start);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // The run's commands by the time they are posted: some stamped earlier than the one before (a
  // scene's readings come back a few steps late), two at one sample whose order matters, one before
  // the start, one past the end, and a burst of 1,500 in one block (more than the synth's queue).
  struct Posted {
    double at;  // run time when posted
    Command command;
  };
  std::vector<Posted> script;
  script.push_back({start, {Command::Kind::Drone, sampleTime(start - 1.0), 1}});
  script.push_back({start, {Command::Kind::Volume, sampleTime(start), 0.7f}});
  for (int i = 0; i < 60; ++i) {
    const double t = start + 0.1 + 5.5 * uniform(random);
    const auto kind = i % 7 == 0 ? Command::Kind::Climax : i % 5 == 0 ? Command::Kind::Volume : Command::Kind::Bell;
    const float value = kind == Command::Kind::Bell ? float(220.0 + 660.0 * uniform(random))
                        : kind == Command::Kind::Volume ? float(uniform(random))
                                                        : kClimaxWet;
    script.push_back({t + 0.05 * uniform(random), {kind, sampleTime(t), value}});  // up to 50 ms late
  }
  script.push_back({start + 2.0, {Command::Kind::Volume, sampleTime(start + 2.0), 0.1f}});
  script.push_back({start + 2.0, {Command::Kind::Volume, sampleTime(start + 2.0), 0.9f}});  // this one wins
  for (int i = 0; i < 1500; ++i)
    script.push_back({start + 3.0, {Command::Kind::Bell, sampleTime(start + 2.95) + i, 300.0f + float(i % 40)}});
  script.push_back({start + 4.0, {Command::Kind::ReverbWet, sampleTime(start + 4.0), 0.5f}});
  script.push_back({start + 6.0, {Command::Kind::Bell, sampleTime(start + 9.0), kE5}});  // after the end
  std::stable_sort(script.begin(), script.end(), [](const Posted& a, const Posted& b) { return a.at < b.at; });

  constexpr double kSeconds = 6.0, kLag = 0.1;
  OfflineRender stretches(run, kSeconds);
  std::vector<float> streamed;
  size_t posted = 0;
  const int64_t ragged[] = {1, 333, 4097, 48000, 2, 1024};
  for (int64_t now = 0, i = 0; stretches.rendered() < stretches.frames(); now += ragged[i++ % 6]) {
    const double runTime = start + double(now) / kSampleRate;
    while (posted < script.size() && script[posted].at <= runTime) run.post(script[posted++].command);
    stretches.renderTo(now - sampleTime(kLag), streamed);
    if (runTime > start + kSeconds + kLag) stretches.renderTo(stretches.frames(), streamed);
  }
  ASSERT_EQ(posted, script.size());
  EXPECT_EQ(stretches.late(), 0u);
  const std::vector<float> whole = run.render(kSeconds);
  ASSERT_EQ(streamed.size(), whole.size());
  EXPECT_EQ(streamed, whole);  // sample for sample
  EXPECT_GT(*std::max_element(whole.begin(), whole.end()), 0.1f);  // and there is something to hear
}

// A command stamped before what has already been rendered cannot land on its sample: it plays at once
// and is counted, so a run can say its sound is not the whole render's.
TEST(AudioEngine, ACommandLaterThanItsStretchIsCounted) {
  OfflineAudio run;
  OfflineRender stretches(run, 1.0);
  std::vector<float> streamed;
  stretches.renderTo(24000, streamed);
  run.bell(0.25, kE4);  // sample 12000, already rendered
  stretches.renderTo(48000, streamed);
  EXPECT_EQ(stretches.late(), 1u);
  EXPECT_EQ(streamed.size(), 2u * 48000u);
  EXPECT_NE(streamed, run.render(1.0));
  EXPECT_EQ(streamed[2 * 24000], 0.0f);  // the attack starts from zero at the first sample after
  EXPECT_NE(streamed[2 * 24001], 0.0f);
}

TEST(AudioEngine, RenderingDoesNotAllocate) {
  Synth synth;
  std::vector<float> out(2 * 512);
  synth.post({Command::Kind::Drone, 0, 1});
  synth.render(out.data(), 512);
  const size_t before = gAllocations.load();
  for (int block = 0; block < 200; ++block) {  // over two seconds of commands and voices
    synth.post({Command::Kind::Bell, kAsSoonAsPossible, kE4});
    if (block == 50) synth.post({Command::Kind::Climax, kAsSoonAsPossible, 0});
    synth.post({Command::Kind::Volume, block * 512 + 100, 0.5f + 0.002f * float(block)});
    synth.render(out.data(), 512);
  }
  EXPECT_EQ(gAllocations.load(), before);
}

// --- The queue ---

TEST(AudioQueue, EveryValueArrivesOnceInOrderAcrossThreads) {
  SpscQueue<uint64_t, 64> queue;  // small, so the two threads wrap it and meet it full and empty
  constexpr uint64_t kCount = 2'000'000;
  std::thread producer([&] {
    for (uint64_t i = 0; i < kCount;)
      if (queue.push(i)) ++i;
  });
  uint64_t expected = 0, wrong = 0;
  while (expected < kCount) {
    if (const uint64_t* value = queue.front()) {
      if (*value != expected) ++wrong;
      queue.pop();
      ++expected;
    }
  }
  producer.join();
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(queue.front(), nullptr);
}

TEST(AudioQueue, SynthTakesCommandsFromAnotherThread) {
  // The frame loop's side and the audio callback's side at once, as in the gallery.
  Synth synth;
  std::atomic<bool> done{false};
  std::thread frameLoop([&] {
    for (int i = 0; i < 5000; ++i)
      while (!synth.post({Command::Kind::Volume, kAsSoonAsPossible, float(i % 2)})) std::this_thread::yield();
    done = true;
  });
  std::vector<float> out(2 * 64);
  while (!done) synth.render(out.data(), 64);
  frameLoop.join();
  synth.render(out.data(), 64);  // drains whatever arrived after the last block
  SUCCEED();
}

// --- WAV ---

class AudioWav : public test::TempFolderTest {};

uint32_t u32(const std::string& b, size_t at) {
  return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 | uint32_t(uint8_t(b[at + 2])) << 16 |
         uint32_t(uint8_t(b[at + 3])) << 24;
}
uint16_t u16(const std::string& b, size_t at) { return uint16_t(uint8_t(b[at]) | uint8_t(b[at + 1]) << 8); }

const std::vector<float> kFrames{0.0f, -0.0f, 0.5f, -0.5f, 1.0f, -1.0f, 2.0f, -3.0f, 0.25f, 1e-6f};

TEST_F(AudioWav, Pcm16HeaderAndSamples) {
  const auto path = folder_ / "out.wav";
  writeWav(path, kFrames, WavFormat::Pcm16);
  const std::string b = test::readFile(path);
  ASSERT_EQ(b.size(), 44u + 20u);
  EXPECT_EQ(b.substr(0, 4), "RIFF");
  EXPECT_EQ(u32(b, 4), 36u + 20u) << "RIFF size: the file less 8 bytes";
  EXPECT_EQ(b.substr(8, 8), "WAVEfmt ");
  EXPECT_EQ(u32(b, 16), 16u);
  EXPECT_EQ(u16(b, 20), 1u) << "PCM";
  EXPECT_EQ(u16(b, 22), 2u) << "channels";
  EXPECT_EQ(u32(b, 24), 48000u);
  EXPECT_EQ(u32(b, 28), 48000u * 4u) << "bytes per second";
  EXPECT_EQ(u16(b, 32), 4u) << "bytes per frame";
  EXPECT_EQ(u16(b, 34), 16u);
  EXPECT_EQ(b.substr(36, 4), "data");
  EXPECT_EQ(u32(b, 40), 20u);
  const std::vector<int16_t> expected{0, 0, 16384, -16384, 32767, -32767, 32767, -32767, 8192, 0};
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(int16_t(u16(b, 44 + 2 * i)), expected[i]) << i;
}

TEST_F(AudioWav, Float32RoundTripsExactly) {
  const auto path = folder_ / "out.wav";
  writeWav(path, kFrames, WavFormat::Float32);
  const std::string b = test::readFile(path);
  ASSERT_EQ(b.size(), 58u + 40u);
  EXPECT_EQ(u32(b, 4), b.size() - 8);
  EXPECT_EQ(u32(b, 16), 18u);
  EXPECT_EQ(u16(b, 20), 3u) << "IEEE float";
  EXPECT_EQ(u32(b, 28), 48000u * 8u);
  EXPECT_EQ(u16(b, 32), 8u);
  EXPECT_EQ(u16(b, 34), 32u);
  EXPECT_EQ(u16(b, 36), 0u) << "no format extension";
  EXPECT_EQ(b.substr(38, 4), "fact");
  EXPECT_EQ(u32(b, 42), 4u);
  EXPECT_EQ(u32(b, 46), 5u) << "frames";
  EXPECT_EQ(b.substr(50, 4), "data");
  EXPECT_EQ(u32(b, 54), 40u);
  for (size_t i = 0; i < kFrames.size(); ++i) EXPECT_EQ(std::bit_cast<float>(u32(b, 58 + 4 * i)), kFrames[i]) << i;
}

TEST_F(AudioWav, RefusesHalfFramesAndUnwritablePaths) {
  EXPECT_THROW(writeWav(folder_ / "odd.wav", std::vector<float>{0.1f, 0.2f, 0.3f}), Error);
  EXPECT_FALSE(std::filesystem::exists(folder_ / "odd.wav"));
  try {
    writeWav(folder_ / "missing" / "x.wav", kFrames);
    FAIL() << "wrote into a folder that does not exist";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing/x.wav"), std::string::npos) << e.what();
  }
  // An empty run is a valid, empty file.
  writeWav(folder_ / "empty.wav", {});
  EXPECT_EQ(u32(test::readFile(folder_ / "empty.wav"), 40), 0u);
}

// --- Output device ---

// A stream's copy of the sound: read in order, and what the reader leaves when the ring is full is
// dropped and counted, never waited for.
TEST(SoundTap, KeepsOrderAndDropsWhatFindsItFull) {
  SoundTap tap;
  std::vector<float> stereo(2 * (SoundTap::kFrames + 100));
  for (size_t i = 0; i < stereo.size(); ++i) stereo[i] = float(i);
  tap.write(stereo.data(), 10);
  std::vector<float> got;
  tap.read(got);
  ASSERT_EQ(got.size(), 20u);
  EXPECT_EQ(got[19], 19.0f);
  tap.write(stereo.data(), SoundTap::kFrames + 100);
  EXPECT_EQ(tap.dropped(), 100u);
  got.clear();
  tap.read(got);
  EXPECT_EQ(got.size(), 2 * SoundTap::kFrames);
}

// Without a device, a stream's tap makes the synth, which then renders on the caller's clock: a bell
// posted after it sounds; before the tap, nothing is rendered.
TEST(AudioOutputDevice, WithoutADeviceTheTapRendersOnTheCallersClock) {
  testing::internal::CaptureStderr();
  AudioOutput output(AudioOutput::Options{.useDevice = false});
  testing::internal::GetCapturedStderr();
  std::vector<float> block(2 * 4800, 0.0f);
  output.bell(0.0, kE4);
  output.renderUnheard(block.data(), 4800);
  EXPECT_EQ(*std::max_element(block.begin(), block.end()), 0.0f);
  output.tap();
  output.bell(0.0, kE4);
  output.renderUnheard(block.data(), 4800);
  EXPECT_GT(*std::max_element(block.begin(), block.end()), 0.01f);
  std::vector<float> tapped;
  output.tap().read(tapped);
  EXPECT_TRUE(tapped.empty());  // nothing is played, so nothing is copied
}


TEST(AudioOutputDevice, WithoutADeviceWarnsOnceAndRunsSilent) {
  testing::internal::CaptureStderr();
  {
    AudioOutput output(AudioOutput::Options{.useDevice = false});
    EXPECT_TRUE(output.silent());
    output.bell(0.0, kE4);
    output.climax(0.0, kClimaxWet);
    output.drone(0.0, true);
    output.reverb(0.0, 0.5f);
    output.setVolume(0.5f);
    output.setMuted(true);
    EXPECT_TRUE(output.muted());
    output.pause();
    output.resume();
  }
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "vitrine: no audio device (not asked to open one): running silent\n");

  // The default device: this machine has none. Whatever RtAudio, ALSA or PulseAudio have to say,
  // one line reaches stderr; where a device does open, nothing does.
  testing::internal::CaptureStderr();
  std::unique_ptr<AudioOutput> output;
  EXPECT_NO_THROW(output = std::make_unique<AudioOutput>());
  output->bell(0.0, kE4);
  output->pause();
  output->resume();
  const bool silent = output->silent();
  output.reset();
  const std::string said = testing::internal::GetCapturedStderr();
  std::printf("default device: %s", silent ? said.c_str() : "opened\n");
  if (silent) {
    EXPECT_EQ(said.rfind("vitrine: no audio device (", 0), 0u) << said;
    EXPECT_NE(said.find("): running silent\n"), std::string::npos) << said;
    EXPECT_EQ(std::count(said.begin(), said.end(), '\n'), 1) << said;
  } else {
    EXPECT_EQ(said, "");
  }
}

}  // namespace
}  // namespace vitrine::audio
