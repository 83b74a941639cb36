#pragma once
// Live audio analysis: band energies and level of the latest window, onsets and beats through aubio.
// One analyser per mono stream; whoever owns the stream (a capture device, a sound file played along
// with the simulation) pushes its samples in order and takes the features once per frame.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace vitrine::live {

// Every value is 0..1 so the modulation layer can use any of them as a control without knowing
// what it measures.
//
// Bands: bass 20-250 Hz, mid 250-4000 Hz, high 4000-16000 Hz (cut at Nyquist; a band above Nyquist
// reads 0). Each is the energy of a periodic-Hann-windowed real FFT (KissFFT) of the last kWindow
// samples, |X[k]|^2 summed over the bins whose centre lies in the band, in dB relative to the energy
// of a full-scale sine (amplitude 1) wholly inside the band, mapped by clamp((dB + 60) / 60, 0, 1):
// a full-scale sine reads 1, each 20 dB less reads 1/3 less, -60 dB and below reads 0.
// `level`: the RMS of the same kWindow samples (unwindowed) in dB relative to a full-scale sine's
// RMS (1/sqrt 2), mapped the same way.
struct AudioFeatures {
  float bass = 0, mid = 0, high = 0, level = 0;  // 0..1 each, see above
  float onset = 0;  // 1 when an onset happened since the previous take(), else 0
  float beat = 0;   // 1 when a beat happened since the previous take(), else 0: aubio's tracked beats, and
                    // the onsets until it knows the tempo (audio_analysis.cpp, pulse())
  float tempo = 0;  // beats per minute from aubio's tempo tracker as of the latest beat, 0 before the first
};

// Analysis runs once per complete hop of kHop samples over the last kWindow samples (zeros before
// the first sample), so results never depend on how the samples were split into pushes.
//
// Onsets: aubio_onset with "hfc" (high-frequency content on a log-compressed spectrum, aubio's
// default): percussive attacks (kicks, claps, hi-hats, a plucked string) are what a picture can
// follow, and hfc marks each once, sharply in time. "complex" also follows tonal change, which is
// its trouble here: on the tests' kick track (a pitch drop under a decay) it found 16 onsets for 8
// kicks, hfc the 8, each within 2.1 ms. Onset times are the onset's position in the signal: aubio's
// detection (a peak picker a few hops behind the signal) reports the frame of the peak less its
// fixed delay of 4.3 hops, aubio_onset_get_last. Beats: aubio_tempo ("default": spectral flux and
// a comb-filter beat tracker over the last ~11 s); its first tempo after about 3 s, then beats
// predicted from it. Silence is what stays under -60 dB mean power (a full-scale sine is -3 dB;
// aubio's own gates of -70 / -90 dB let microphone hiss through): no onset is reported in a silent
// hop, no beat unless a hop within the last 1.5 beat periods was heard (a predicted beat may fall
// in the gap just before its drum). The tempo is aubio's at the latest beat counted, so it holds
// through a pause rather than drifting to what the tracker makes of silence.
//
// Not thread-safe: one thread pushes and takes. Non-copyable; movable (a moved-from analyser may
// only be destroyed or assigned to).
class AudioAnalyser {
 public:
  static constexpr size_t kWindow = 1024, kHop = 256;
  // Onset and beat times kept, the oldest dropped first.
  static constexpr size_t kKeptTimes = 4096;

  // Throws vitrine::Error for a sample rate that is not a finite number from 1000 to 768000 Hz.
  explicit AudioAnalyser(double sampleRate);
  // An analyser that joins a stream at sample `firstSample` (after a jump): its times count from the
  // stream's start, and its hops fall where they would have from 0 when firstSample is a multiple of
  // kHop.
  AudioAnalyser(double sampleRate, uint64_t firstSample);
  ~AudioAnalyser();
  AudioAnalyser(AudioAnalyser&&) noexcept;
  AudioAnalyser& operator=(AudioAnalyser&&) noexcept;
  AudioAnalyser(const AudioAnalyser&) = delete;
  AudioAnalyser& operator=(const AudioAnalyser&) = delete;

  // Mono samples in order, any block size. A sample that is not finite is taken as 0, so one bad
  // sample cannot poison aubio's running state for good.
  void push(std::span<const float> mono);

  // Features of the latest complete hop; onset and beat are 1 when any hop since the last take()
  // had one (a frame never misses a pulse), then cleared.
  AudioFeatures take();

  // Times (seconds from the first sample pushed, or from the stream's start for an analyser that
  // joined it at firstSample) of every onset / beat found so far, in order; the last kKeptTimes of each.
  const std::vector<double>& onsetTimes() const;
  const std::vector<double>& beatTimes() const;
  double sampleRate() const;
  // Seconds from a sound reaching push() to features that include it: up to one hop before its
  // hop is complete, plus the window it is analysed in ((kHop + kWindow) / rate: 26.7 ms at 48 kHz).
  // Onset flags come about as late: aubio finds an onset 4 to 5 hops after it.
  double latencySeconds() const;
  // The stream position of the next sample: firstSample + the samples pushed so far.
  uint64_t streamPosition() const;

  // The sound itself, for pictures that draw it (ISF's audio and audioFFT inputs), as of the latest
  // complete hop: the last kWindow samples, oldest first; and their spectrum, kWindow / 2 bins from DC
  // up, each bin's magnitude (the same Hann-windowed FFT as the bands) in dB relative to the peak bin
  // of a full-scale sine, mapped 0..1 as the bands are.
  std::span<const float> recentSamples() const;
  std::vector<float> spectrum() const;

 private:
  struct State;
  void analyseHop();
  std::unique_ptr<State> state_;
};

}  // namespace vitrine::live
