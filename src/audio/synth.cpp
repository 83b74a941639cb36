#include "audio/synth.h"

#include <kissfft/kiss_fftr.h>

#include <algorithm>
#include <complex>
#include <new>
#include <numbers>
#include <stdexcept>

#include "maths/hash.h"

namespace vitrine::audio {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// The sample at which a bell voice falls silent and frees itself: 144 + 86400.
constexpr int64_t kBellEnd = int64_t((kBellAttack + kBellDecay) * kSampleRate + 0.5);

// Advances a phase in cycles and keeps it in [0, 1), where sin() is most precise.
double advance(double& phase, double hz) {
  const double now = phase;
  phase += hz / kSampleRate;
  if (phase >= 1.0) phase -= 1.0;
  return now;
}

}  // namespace

// --- Ramp ---

void Ramp::set(float target, double seconds) {
  target_ = target;
  remaining_ = seconds > 0.0 ? std::max<int64_t>(1, toSamples(seconds)) : 0;
  if (remaining_ == 0) {
    value_ = target;
    step_ = 0.0;
    return;
  }
  step_ = (double(target) - value_) / double(remaining_);
}

float Ramp::next() {
  if (remaining_ > 0) {
    value_ += step_;
    if (--remaining_ == 0) value_ = target_;  // land exactly, whatever the rounding on the way
  }
  return float(value_);
}

// --- Biquad ---

Biquad Biquad::lowPass(double cutoffHz, double q) {
  const double w0 = kTwoPi * cutoffHz / kSampleRate;
  const double alpha = std::sin(w0) / (2.0 * q);
  const double c = std::cos(w0);
  const double a0 = 1.0 + alpha;
  Biquad f;
  f.b0_ = (1.0 - c) / 2.0 / a0;
  f.b1_ = (1.0 - c) / a0;
  f.b2_ = f.b0_;
  f.a1_ = -2.0 * c / a0;
  f.a2_ = (1.0 - alpha) / a0;
  return f;
}

float Biquad::process(float x) {
  const double y = b0_ * x + b1_ * x1_ + b2_ * x2_ - a1_ * y1_ - a2_ * y2_;
  x2_ = x1_;
  x1_ = x;
  y2_ = y1_;
  y1_ = y;
  return float(y);
}

double Biquad::magnitudeAt(double hz) const {
  const std::complex<double> z1 = std::polar(1.0, -kTwoPi * hz / kSampleRate);  // z^-1 on the unit circle
  const std::complex<double> z2 = z1 * z1;
  return std::abs((b0_ + b1_ * z1 + b2_ * z2) / (1.0 + a1_ * z1 + a2_ * z2));
}

// --- Drone ---

Drone::Drone() : filter_(Biquad::lowPass(kDroneCutoffHz, 0.707)) {}

void Drone::setOn(bool on) { gain_.set(on ? 1.0f : 0.0f, kDroneFade); }

float Drone::next() {
  const double root = std::sin(kTwoPi * advance(rootPhase_, kDroneRootHz));
  const double octave = std::sin(kTwoPi * advance(octavePhase_, kDroneOctaveHz));
  // The filter runs while the drone is off too, so fading in starts from a settled state.
  const float filtered = filter_.process(float(root + kDroneOctaveAmplitude * octave));
  return filtered * kDroneLevel * gain_.next();
}

// --- Bells ---

double bellEnvelope(double t) {
  if (t < 0.0) return 0.0;
  if (t < kBellAttack) return t / kBellAttack;
  const double decaying = t - kBellAttack;
  if (decaying >= kBellDecay) return 0.0;
  return std::exp(-decaying / kBellTau);
}

void BellVoice::start(float hz, float level, std::span<const Partial> partials, int64_t started) {
  partialCount_ = std::min(partials.size(), partials_.size());
  std::copy_n(partials.begin(), partialCount_, partials_.begin());
  phase_ = 0.0;
  increment_ = double(hz) / kSampleRate;
  level_ = level;
  age_ = 0;
  started_ = started;
  active_ = true;
}

float BellVoice::next() {
  if (!active_) return 0.0f;
  if (age_ >= kBellEnd) {
    active_ = false;
    return 0.0f;
  }
  // The phase is not wrapped: 1.8 s of the highest bell is ~1200 cycles, where a double still
  // resolves 1e-13 of a cycle, and every partial is then exactly in step with the fundamental.
  double sum = 0.0;
  for (size_t i = 0; i < partialCount_; ++i)
    sum += partials_[i].amplitude * std::sin(kTwoPi * partials_[i].ratio * phase_);
  const double envelope = bellEnvelope(double(age_) / kSampleRate);
  phase_ += increment_;
  ++age_;
  return float(level_ * envelope * sum);
}

// --- Plate impulse ---

std::vector<float> plateImpulse(uint32_t seed, double seconds) {
  const size_t length = size_t(std::max<int64_t>(1, toSamples(seconds)));
  std::vector<float> impulse(length);
  double energy = 0.0;
  for (size_t i = 0; i < length; ++i) {
    const float noise = 2.0f * maths::hash01(glm::uvec3(uint32_t(i), seed, 0x706c6174u)) - 1.0f;
    const double shape = std::pow(1.0 - double(i) / double(length), kPlateShape);
    impulse[i] = float(noise * shape);
    energy += double(impulse[i]) * impulse[i];
  }
  const float scale = energy > 0.0 ? float(1.0 / std::sqrt(energy)) : 0.0f;
  for (float& h : impulse) h *= scale;
  return impulse;
}

// --- Partitioned convolution ---

struct PartitionedConvolver::Fft {
  size_t bins = 0;  // block + 1 complex values per real FFT of 2 x block
  kiss_fftr_cfg forward = nullptr, inverse = nullptr;
  std::vector<kiss_fft_cpx> filters;  // partition p at [p * bins, (p + 1) * bins)
  std::vector<kiss_fft_cpx> history;  // the last `partitions` input spectra, a ring
  size_t newest = 0;                  // history slot of the latest input spectrum
  std::vector<kiss_fft_cpx> sum;
  std::vector<float> time;  // 2 x block
  ~Fft() {
    kiss_fftr_free(forward);
    kiss_fftr_free(inverse);
  }
};

PartitionedConvolver::PartitionedConvolver(std::span<const float> impulse, size_t blockSize)
    : fft_(std::make_unique<Fft>()), block_(blockSize) {
  if (block_ < 2 || block_ % 2 != 0) throw std::invalid_argument("convolution block size must be even");
  partitions_ = std::max<size_t>(1, (impulse.size() + block_ - 1) / block_);
  const size_t n = 2 * block_;
  Fft& f = *fft_;
  f.bins = block_ + 1;
  f.forward = kiss_fftr_alloc(int(n), 0, nullptr, nullptr);
  f.inverse = kiss_fftr_alloc(int(n), 1, nullptr, nullptr);
  if (!f.forward || !f.inverse) throw std::bad_alloc();
  f.filters.resize(partitions_ * f.bins);
  f.history.assign(partitions_ * f.bins, kiss_fft_cpx{0, 0});
  f.sum.resize(f.bins);
  f.time.assign(n, 0.0f);
  // Each partition zero-padded to 2 x block: overlap-save keeps the half of every circular
  // convolution that did not wrap. KissFFT's inverse does not divide by n; the filters do.
  for (size_t p = 0; p < partitions_; ++p) {
    std::fill(f.time.begin(), f.time.end(), 0.0f);
    const size_t first = p * block_, count = std::min(block_, impulse.size() - first);
    for (size_t i = 0; i < count; ++i) f.time[i] = impulse[first + i] / float(n);
    kiss_fftr(f.forward, f.time.data(), &f.filters[p * f.bins]);
  }
  window_.assign(n, 0.0f);
  output_.assign(block_, 0.0f);
}

PartitionedConvolver::~PartitionedConvolver() = default;

float PartitionedConvolver::process(float x) {
  const float y = output_[filled_];
  window_[block_ + filled_] = x;
  if (++filled_ == block_) {
    processBlock();
    filled_ = 0;
  }
  return y;
}

void PartitionedConvolver::processBlock() {
  Fft& f = *fft_;
  kiss_fftr(f.forward, window_.data(), &f.history[f.newest * f.bins]);
  // Y = sum over p of X(block - p) H(p): the spectrum from p blocks ago meets partition p.
  std::fill(f.sum.begin(), f.sum.end(), kiss_fft_cpx{0, 0});
  for (size_t p = 0; p < partitions_; ++p) {
    const kiss_fft_cpx* x = &f.history[((f.newest + partitions_ - p) % partitions_) * f.bins];
    const kiss_fft_cpx* h = &f.filters[p * f.bins];
    for (size_t b = 0; b < f.bins; ++b) {
      f.sum[b].r += x[b].r * h[b].r - x[b].i * h[b].i;
      f.sum[b].i += x[b].r * h[b].i + x[b].i * h[b].r;
    }
  }
  kiss_fftri(f.inverse, f.sum.data(), f.time.data());
  std::copy(f.time.begin() + block_, f.time.end(), output_.begin());
  std::copy(window_.begin() + block_, window_.end(), window_.begin());  // this block becomes the previous
  f.newest = (f.newest + 1) % partitions_;
}

// --- Wet envelope ---

void WetEnvelope::climax(float wet) {
  climaxWet_ = std::clamp(wet, 0.0f, 1.0f);
  holdLeft_ = toSamples(kWetRamp + kWetHold);
  if (!override_) ramp_.set(climaxWet_, kWetRamp);
}

void WetEnvelope::setOverride(std::optional<float> wet) {
  if (wet) wet = std::clamp(*wet, 0.0f, 1.0f);
  override_ = wet;
  ramp_.set(override_ ? *override_ : automaticTarget(), kWetRamp);
}

float WetEnvelope::next() {
  const float wet = ramp_.next();
  if (holdLeft_ > 0 && --holdLeft_ == 0 && !override_) ramp_.set(0.0f, kWetRamp);
  return wet;
}

// --- Limiter ---

Limiter::Limiter(float ceiling, double releaseSeconds)
    : ceiling_(ceiling), recover_(float(1.0 - std::exp(-1.0 / (releaseSeconds * kSampleRate)))) {}

float Limiter::process(float x) {
  if (!std::isfinite(x)) x = 0.0f;
  gain_ += (1.0f - gain_) * recover_;
  const float magnitude = std::abs(x);
  if (magnitude * gain_ > ceiling_) gain_ = ceiling_ / magnitude;
  return x * gain_;
}

}  // namespace vitrine::audio
