#pragma once
// A sound file as live input, frame-exact with the simulation clock: each frame analyses exactly
// the samples the file has played by then, so a recorded run and a live one see the same features.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "live/audio_analysis.h"
#include "live/audio_clip.h"

namespace vitrine::live {

class AudioFileInput {
 public:
  // A jump forward of more than this (a run started late with --time, a seek) restarts the analysis
  // this long before the new time rather than analysing everything in between: long enough for
  // the tempo tracker (an ~11 s window) to know the tempo again.
  static constexpr double kCatchUpSeconds = 30.0;

  // File time 0 plays at simulation time `start`. Throws vitrine::Error (readAudioFile's).
  AudioFileInput(const std::filesystem::path& path, bool loop, double start = 0.0);
  // The same for a clip already in memory (tests, a clip shared with the sound track). Throws
  // vitrine::Error for a clip with no frames or a sample rate AudioAnalyser refuses.
  AudioFileInput(AudioClip clip, bool loop, double start = 0.0);

  // Feeds the analyser every sample before simulation time `seconds` and returns its take(). Time
  // only moves forward (an earlier or non-finite time feeds nothing); when `loop` the file repeats
  // (the analyser hears one continuous stream), else silence follows its end. Deterministic: the
  // same sequence of times gives the same features, whatever the step, except that a jump over
  // kCatchUpSeconds starts a fresh analyser kCatchUpSeconds before the new time. A time on a
  // sample (within a millionth of one) counts that sample as after it, so 2/60 and 1/30 agree.
  AudioFeatures at(double seconds);

  const AudioClip& clip() const { return clip_; }
  const std::vector<float>& mono() const { return mono_; }  // the clip's channels averaged, as analysed
  // The analyser now running: after a jump, a fresh one (its times still count from file time 0).
  const AudioAnalyser& analyser() const { return analyser_; }

 private:
  void feed(uint64_t end);

  AudioClip clip_;
  std::vector<float> mono_;
  bool loop_;
  double start_;
  AudioAnalyser analyser_;
  std::vector<float> scratch_;
};

}  // namespace vitrine::live
