#include "live/audio_analysis.h"

#include <aubio/aubio.h>
#include <fmt/format.h>
#include <kissfft/kiss_fftr.h>

#include <algorithm>
#include <optional>
#include <cmath>
#include <numbers>
#include <type_traits>

#include "core/error.h"

namespace vitrine::live {

static_assert(std::is_same_v<smpl_t, float>, "aubio built for doubles: its hops would need converting");

namespace {

// Below this mean power (dB re full scale, aubio's measure: a full-scale sine is -3 dB) a hop is
// silent to aubio: no onset or beat is reported there. Room noise through a microphone sits around
// -70 dB; aubio's defaults (-70 for onsets, -90 for beats) would let its flutter through.
constexpr float kSilenceDb = -60.0f;

// aubio counts samples in 32-bit integers (2^32 samples: 24.8 hours at 48 kHz) and compares onset
// positions with them, so past the wrap it would suppress every onset for as long again. Its onset
// counters are reset every 2^22 hops (6.2 hours at 48 kHz), long before.
constexpr uint64_t kOnsetResetHops = uint64_t(1) << 22;

// A beat is predicted, so it may fall in a silent gap just before the kick it follows (digital
// silence between the drums of a drum machine): it counts when the loudest hop in the last beat
// period and a half was not silent. Hop powers are kept this long: 1.5 periods at 36 BPM.
constexpr double kLoudnessMemorySeconds = 2.5;

// Maps dB re full scale onto 0..1: 0 dB reads 1, -60 dB and below 0.
float unit(double db) { return float(std::clamp((db + 60.0) / 60.0, 0.0, 1.0)); }

struct Band {
  double lo, hi;
};
constexpr Band kBass{20.0, 250.0}, kMid{250.0, 4000.0}, kHigh{4000.0, 16000.0};

}  // namespace

struct AudioAnalyser::State {
  double rate = 0;
  std::vector<float> hann;    // periodic Hann, kWindow
  std::vector<float> recent;  // the last kWindow samples as of the latest complete hop
  size_t filled = 0;          // samples of the current hop gathered in `hop`
  uint64_t first = 0;         // the stream position of the first sample pushed
  uint64_t hops = 0;          // complete hops analysed
  uint64_t onsetResetHop = 0;  // the hop at which aubio's onset counters last started from 0
  uint_t lastBeat = 0;         // aubio_tempo_get_last before the latest hop
  float tempoBpm = 0;          // aubio's tempo at the latest beat counted
  std::vector<float> hopDb;    // mean power of recent hops in dB, a ring indexed by hop
  bool onsetSince = false, beatSince = false, bandsStale = false;
  std::optional<uint64_t> pulseHop;  // the hop of the latest beat pulse (see pulse())
  AudioFeatures latest;
  std::vector<double> onsetTimes, beatTimes;

  // Band bins [first, end) of the one-sided spectrum, and the energy a full-scale sine gives.
  size_t bassBins[2]{}, midBins[2]{}, highBins[2]{};
  double fullScale = 1;
  kiss_fftr_cfg fft = nullptr;
  std::vector<float> windowed;
  std::vector<kiss_fft_cpx> spectrum;

  fvec_t* hop = nullptr;  // the hop being gathered, then handed to aubio
  fvec_t* onsetOut = nullptr;
  fvec_t* tempoOut = nullptr;
  aubio_onset_t* onset = nullptr;
  aubio_tempo_t* tempo = nullptr;

  ~State() {
    if (tempo) del_aubio_tempo(tempo);
    if (onset) del_aubio_onset(onset);
    if (tempoOut) del_fvec(tempoOut);
    if (onsetOut) del_fvec(onsetOut);
    if (hop) del_fvec(hop);
    kiss_fftr_free(fft);
  }

  void setBins(size_t (&bins)[2], Band band) const {
    // Bins whose centre frequency k x rate / kWindow lies in [lo, min(hi, Nyquist)); DC and the
    // Nyquist bin belong to no band.
    const double hi = std::min(band.hi, rate / 2.0), step = rate / double(kWindow);
    bins[0] = std::max<size_t>(1, size_t(std::ceil(band.lo / step)));
    bins[1] = std::max(bins[0], std::min<size_t>(kWindow / 2, size_t(std::ceil(hi / step))));
  }

  // The beat a picture follows: aubio's tracked beats once it knows the tempo, and until then (its
  // first ~3 s) the onsets, so a track's first bar is not dead. A pulse never follows another within
  // half a beat (150 ms before the tempo is known): the handover from onsets to beats, where both
  // mark one kick a few ms apart, gives one pulse, not two.
  void pulse() {
    const double gap = tempoBpm > 0.0f ? 30.0 / double(tempoBpm) : 0.15;
    if (pulseHop && double((hops - *pulseHop) * kHop) < gap * rate) return;
    beatSince = true;
    pulseHop = hops;
  }

  void keep(std::vector<double>& times, double t) {
    if (times.size() == kKeptTimes) times.erase(times.begin());
    times.push_back(t);
  }

  // Whether any of the hops within the last `samples` (this one included) was above the gate.
  bool heardWithin(double samples) const {
    const auto n = std::min<uint64_t>({hopDb.size(), hops + 1, uint64_t(std::ceil(samples / double(kHop))) + 1});
    for (uint64_t i = 0; i < n; ++i)
      if (hopDb[(hops - i) % hopDb.size()] >= kSilenceDb) return true;
    return false;
  }

  void computeBands() {
    for (size_t i = 0; i < kWindow; ++i) windowed[i] = recent[i] * hann[i];
    kiss_fftr(fft, windowed.data(), spectrum.data());
    const auto band = [&](const size_t(&bins)[2]) {
      double energy = 0;
      for (size_t k = bins[0]; k < bins[1]; ++k)
        energy += double(spectrum[k].r) * spectrum[k].r + double(spectrum[k].i) * spectrum[k].i;
      return unit(10.0 * std::log10(energy / fullScale));
    };
    latest.bass = band(bassBins);
    latest.mid = band(midBins);
    latest.high = band(highBins);
    double power = 0;
    for (float s : recent) power += double(s) * s;
    // RMS x sqrt(2): a full-scale sine's RMS is 1/sqrt(2), and it reads 0 dB.
    latest.level = unit(10.0 * std::log10(2.0 * power / double(kWindow)));
    bandsStale = false;
  }
};

AudioAnalyser::AudioAnalyser(double sampleRate) : AudioAnalyser(sampleRate, 0) {}

AudioAnalyser::AudioAnalyser(double sampleRate, uint64_t firstSample) : state_(std::make_unique<State>()) {
  if (!(sampleRate >= 1000.0 && sampleRate <= 768000.0))
    throw Error(fmt::format("Cannot analyse sound at {} Hz: the sample rate must be from 1000 to 768000 Hz",
                            sampleRate));
  State& s = *state_;
  s.rate = sampleRate;
  s.first = firstSample;
  s.hann.resize(kWindow);
  for (size_t i = 0; i < kWindow; ++i)
    s.hann[i] = float(0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * double(i) / double(kWindow)));
  s.recent.assign(kWindow, 0.0f);
  s.windowed.resize(kWindow);
  s.spectrum.resize(kWindow / 2 + 1);
  s.setBins(s.bassBins, kBass);
  s.setBins(s.midBins, kMid);
  s.setBins(s.highBins, kHigh);
  // A sine of amplitude 1 windowed by w has N x sum(w^2) / 2 energy over the whole spectrum
  // (Parseval), half of it in the one-sided bins summed.
  double sumSquares = 0;
  for (float w : s.hann) sumSquares += double(w) * w;
  s.fullScale = double(kWindow) * sumSquares / 4.0;
  s.fft = kiss_fftr_alloc(int(kWindow), 0, nullptr, nullptr);
  s.hopDb.assign(size_t(std::ceil(kLoudnessMemorySeconds * sampleRate / double(kHop))), -1000.0f);

  const auto rate = uint_t(std::lround(sampleRate));
  s.hop = new_fvec(kHop);
  s.onsetOut = new_fvec(1);
  s.tempoOut = new_fvec(1);
  s.onset = new_aubio_onset("hfc", kWindow, kHop, rate);
  s.tempo = new_aubio_tempo("default", kWindow, kHop, rate);
  if (!s.fft || !s.hop || !s.onsetOut || !s.tempoOut || !s.onset || !s.tempo)
    throw Error(fmt::format("Cannot set up audio analysis at {} Hz: out of memory", sampleRate));
  aubio_onset_set_silence(s.onset, kSilenceDb);
  aubio_tempo_set_silence(s.tempo, kSilenceDb);
}

AudioAnalyser::~AudioAnalyser() = default;
AudioAnalyser::AudioAnalyser(AudioAnalyser&&) noexcept = default;
AudioAnalyser& AudioAnalyser::operator=(AudioAnalyser&&) noexcept = default;

void AudioAnalyser::push(std::span<const float> mono) {
  State& s = *state_;
  while (!mono.empty()) {
    const size_t n = std::min(kHop - s.filled, mono.size());
    float* to = s.hop->data + s.filled;
    for (size_t i = 0; i < n; ++i) to[i] = std::isfinite(mono[i]) ? mono[i] : 0.0f;
    s.filled += n;
    mono = mono.subspan(n);
    if (s.filled == kHop) {
      analyseHop();
      s.filled = 0;
    }
  }
}

void AudioAnalyser::analyseHop() {
  State& s = *state_;
  std::copy(s.recent.begin() + kHop, s.recent.end(), s.recent.begin());
  std::copy(s.hop->data, s.hop->data + kHop, s.recent.end() - kHop);
  s.bandsStale = true;
  // aubio counts from the first sample it was given; times count from the stream's start.
  const uint64_t hopStart = s.hops * kHop;

  const bool reset = s.hops - s.onsetResetHop == kOnsetResetHops;
  if (reset) {
    aubio_onset_reset(s.onset);
    s.onsetResetHop = s.hops;
  }
  aubio_onset_do(s.onset, s.hop, s.onsetOut);
  // After a reset aubio takes any sound in its first hop for the start of a file, an onset at 0:
  // that one is not in the signal.
  if (s.onsetOut->data[0] > 0.0f && !reset) {
    s.onsetSince = true;
    if (s.tempoBpm == 0.0f) s.pulse();
    const uint64_t at = s.first + s.onsetResetHop * kHop + aubio_onset_get_last(s.onset);
    s.keep(s.onsetTimes, double(at) / s.rate);
  }

  s.hopDb[s.hops % s.hopDb.size()] = std::max(-1000.0f, float(aubio_db_spl(s.hop)));
  aubio_tempo_do(s.tempo, s.hop, s.tempoOut);
  // aubio marks a beat by its fractional position within the hop, which may be exactly 0, and
  // moves its last beat even in a silent hop (where it clears the mark): a beat is a new last beat
  // where the music was heard within the last period and a half.
  const uint_t last = aubio_tempo_get_last(s.tempo);
  if (last != s.lastBeat && s.heardWithin(1.5 * double(aubio_tempo_get_period(s.tempo)))) {
    s.tempoBpm = std::max(0.0f, float(aubio_tempo_get_bpm(s.tempo)));
    s.pulse();
    // aubio's position wraps at 2^32 samples; its distance from this hop's start does not.
    const auto offset = int32_t(uint32_t(last - uint_t(hopStart)));
    s.keep(s.beatTimes, double(int64_t(s.first + hopStart) + offset) / s.rate);
  }
  s.lastBeat = last;
  ++s.hops;
}

AudioFeatures AudioAnalyser::take() {
  State& s = *state_;
  if (s.bandsStale) s.computeBands();
  AudioFeatures features = s.latest;
  features.onset = s.onsetSince ? 1.0f : 0.0f;
  features.beat = s.beatSince ? 1.0f : 0.0f;
  features.tempo = s.tempoBpm;
  s.onsetSince = s.beatSince = false;
  return features;
}

const std::vector<double>& AudioAnalyser::onsetTimes() const { return state_->onsetTimes; }
const std::vector<double>& AudioAnalyser::beatTimes() const { return state_->beatTimes; }
double AudioAnalyser::sampleRate() const { return state_->rate; }
double AudioAnalyser::latencySeconds() const { return double(kHop + kWindow) / state_->rate; }
uint64_t AudioAnalyser::streamPosition() const { return state_->first + state_->hops * kHop + state_->filled; }

std::span<const float> AudioAnalyser::recentSamples() const { return state_->recent; }

std::vector<float> AudioAnalyser::spectrum() const {
  State& s = *state_;  // the bands' FFT, computed once per hop whoever asks first
  if (s.bandsStale) s.computeBands();
  // A full-scale sine on a bin's centre: |X| = N/4 under a periodic Hann window (its mean is 1/2).
  const double peak = double(kWindow) / 4.0;
  std::vector<float> bins(kWindow / 2);
  for (size_t k = 0; k < bins.size(); ++k) {
    const double magnitude = std::hypot(double(s.spectrum[k].r), double(s.spectrum[k].i));
    bins[k] = magnitude > 0.0 ? unit(20.0 * std::log10(magnitude / peak)) : 0.0f;
  }
  return bins;
}

}  // namespace vitrine::live
