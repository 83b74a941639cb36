#pragma once
// The sound's maths, free of devices, threads and time keeping: the drone, bell voices, the plate
// reverb (its impulse and a partitioned FFT convolution), the wet envelope and the master limiter.
// Everything is mono float at kSampleRate; engine.h mixes, schedules and plays.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace vitrine::audio {

inline constexpr int kSampleRate = 48000;

// Whole samples in a span of seconds, rounded to the nearest.
inline int64_t toSamples(double seconds) { return std::llround(seconds * kSampleRate); }

// --- Levels and timings (linear amplitudes; 1.0 is full scale) ---

// The drone: a 55 Hz sine plus a detuned octave at 110.3 Hz at half its amplitude, low-passed at
// 180 Hz. kDroneLevel scales the two sines so the filtered sum peaks at about 0.12.
inline constexpr float kDroneRootHz = 55.0f;
inline constexpr float kDroneOctaveHz = 110.3f;
inline constexpr float kDroneOctaveAmplitude = 0.5f;
inline constexpr float kDroneCutoffHz = 180.0f;
inline constexpr float kDroneLevel = 0.082f;
inline constexpr double kDroneFade = 0.5;  // seconds to fade in or out

// A bell: partials at whole multiples of its pitch. kBellAttack seconds of linear rise, then
// amplitude e^(-t/tau) with tau = kBellDecay / ln(1000): down 60 dB kBellDecay seconds after the
// attack, where the voice ends (the step from 1/1000 of the voice level to silence, 1.8e-4 of
// full scale for a bell, is far below hearing over the drone).
struct Partial {
  float ratio;      // multiple of the pitch
  float amplitude;  // relative to the fundamental
};
inline constexpr std::array<Partial, 3> kBellPartials{{{1, 1.0f}, {2, 0.3f}, {3, 0.14f}}};
// The climax bells ring brighter: the same partials plus a sixth harmonic.
inline constexpr std::array<Partial, 4> kClimaxPartials{{{1, 1.0f}, {2, 0.3f}, {3, 0.14f}, {6, 0.08f}}};
inline constexpr double kBellAttack = 0.003;
inline constexpr double kBellDecay = 1.8;
inline constexpr double kBellTau = kBellDecay / 6.907755278982137;  // ln(1000): 0.26058 s
inline constexpr float kBellLevel = 0.18f;
// The climax chord. Four bells at 0.12 cannot exceed 4 x 0.12 x 1.52 = 0.73 even with every
// partial in phase, so the chord alone never needs the limiter.
inline constexpr std::array<float, 4> kClimaxChordHz{220.0f, 330.0f, 495.0f, 660.0f};
inline constexpr float kClimaxLevel = 0.12f;

// The plate: 300 ms of seeded white noise shaped by (1 - t/len)^2.2.
inline constexpr double kPlateLength = 0.3;
inline constexpr double kPlateShape = 2.2;
inline constexpr uint32_t kPlateSeed = 0x5eed;
// The wet amount a climax opens the plate to, the ramps and how long it stays open.
inline constexpr float kClimaxWet = 0.28f;
inline constexpr double kWetRamp = 0.3;
inline constexpr double kWetHold = 6.0;

// Master volume and mute glide over this long instead of jumping (a jump is a click).
inline constexpr double kLevelGlide = 0.02;

// --- Building blocks ---

// A linear glide to a target over a fixed number of samples; next() yields one value per sample
// and lands exactly on the target.
class Ramp {
 public:
  explicit Ramp(float value = 0.0f) : value_(value), target_(value) {}
  // Starts from the current value; seconds <= 0 jumps.
  void set(float target, double seconds);
  float next();
  float value() const { return float(value_); }
  float target() const { return target_; }

 private:
  double value_;
  float target_;
  double step_ = 0.0;
  int64_t remaining_ = 0;
};

// RBJ cookbook biquad low-pass (two poles), direct form I in double precision: at 180 Hz and
// 48 kHz the poles sit close to 1, where float coefficients would detune the filter.
class Biquad {
 public:
  static Biquad lowPass(double cutoffHz, double q);
  float process(float x);
  // |H| at a frequency: what the filter does to a steady sine.
  double magnitudeAt(double hz) const;

 private:
  double b0_ = 1, b1_ = 0, b2_ = 0, a1_ = 0, a2_ = 0;  // normalised by a0
  double x1_ = 0, x2_ = 0, y1_ = 0, y2_ = 0;
};

// The drone, faded in and out by setOn.
class Drone {
 public:
  Drone();
  void setOn(bool on);
  bool on() const { return gain_.target() > 0.0f; }
  float next();

 private:
  double rootPhase_ = 0, octavePhase_ = 0;  // in cycles, [0, 1)
  Biquad filter_;
  Ramp gain_;
};

// The amplitude t seconds after a bell starts: 0 at t = 0, 1 at kBellAttack, then the decay;
// 0 from kBellAttack + kBellDecay on.
double bellEnvelope(double t);

// One bell voice of a preallocated pool.
class BellVoice {
 public:
  // Partials beyond four are ignored; `started` orders voices so the oldest can be stolen.
  void start(float hz, float level, std::span<const Partial> partials, int64_t started);
  float next();
  bool active() const { return active_; }
  int64_t started() const { return started_; }

 private:
  std::array<Partial, 4> partials_{};
  size_t partialCount_ = 0;
  double phase_ = 0, increment_ = 0;  // cycles of the fundamental
  float level_ = 0;
  int64_t age_ = 0, started_ = 0;
  bool active_ = false;
};

// The plate's impulse response: `seconds` of white noise (uniform in [-1, 1) from a seeded
// integer hash, so a seed gives the same response on every machine), times (1 - t/len)^2.2,
// scaled to unit energy (the squares sum to 1) so the reverb passes white noise at its level.
std::vector<float> plateImpulse(uint32_t seed, double seconds = kPlateLength);

// Uniformly partitioned convolution, overlap-save with a frequency-domain delay line: the impulse
// is cut into partitions of blockSize samples, each transformed once (real FFT of 2 x blockSize);
// each input block then costs one forward and one inverse FFT plus a multiply-add per partition,
// instead of a multiply-add per impulse sample per output sample. All buffers are allocated here;
// process() never allocates. The output lags the input by latency() = blockSize samples (5.3 ms
// at 256), which the plate turns into a short pre-delay.
class PartitionedConvolver {
 public:
  explicit PartitionedConvolver(std::span<const float> impulse, size_t blockSize = 256);
  ~PartitionedConvolver();
  PartitionedConvolver(const PartitionedConvolver&) = delete;
  PartitionedConvolver& operator=(const PartitionedConvolver&) = delete;

  // One sample in, one out: the convolution's output from latency() samples ago.
  float process(float x);
  size_t latency() const { return block_; }
  size_t partitions() const { return partitions_; }

 private:
  void processBlock();

  struct Fft;  // KissFFT's plans and spectra, kept out of this header
  std::unique_ptr<Fft> fft_;
  size_t block_, partitions_;
  std::vector<float> window_;  // the previous and the current input block: 2 x block_
  std::vector<float> output_;  // the last block's results, played out while the next fills
  size_t filled_ = 0;
};

// The reverb's wet amount: 0 until a climax, then open to kClimaxWet over kWetRamp, held kWetHold
// seconds, closed over kWetRamp (another climax meanwhile restarts the hold). An override fixes
// the amount (ramping to it) until cleared; the climax timing keeps counting underneath.
class WetEnvelope {
 public:
  void climax(float wet = kClimaxWet);
  void setOverride(std::optional<float> wet);
  float next();
  float value() const { return ramp_.value(); }

 private:
  float automaticTarget() const { return holdLeft_ > 0 ? climaxWet_ : 0.0f; }
  float climaxWet_ = kClimaxWet;
  Ramp ramp_;
  int64_t holdLeft_ = 0;  // samples until the automatic wet closes
  std::optional<float> override_;
};

// The last stage: keeps every sample within +-ceiling. The gain drops at once to exactly what a
// loud sample needs (so nothing gets past, with no look-ahead latency), then recovers towards 1
// with the release time constant. Non-finite input becomes silence rather than reaching a device.
class Limiter {
 public:
  explicit Limiter(float ceiling = 0.98f, double releaseSeconds = 0.15);
  float process(float x);
  float gain() const { return gain_; }

 private:
  float ceiling_, recover_, gain_ = 1.0f;
};

}  // namespace vitrine::audio
