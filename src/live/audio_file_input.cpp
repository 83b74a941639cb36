#include "live/audio_file_input.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.h"

namespace vitrine::live {

namespace {

AudioClip checked(AudioClip clip) {
  if (clip.frames() == 0) throw Error("Cannot play an empty sound clip as live input: it has no frames");
  return clip;
}

}  // namespace

AudioFileInput::AudioFileInput(const std::filesystem::path& path, bool loop, double start)
    : AudioFileInput(readAudioFile(path), loop, start) {}

AudioFileInput::AudioFileInput(AudioClip clip, bool loop, double start)
    : clip_(checked(std::move(clip))),
      mono_(monoMix(clip_)),
      loop_(loop),
      start_(std::isfinite(start) ? start : 0.0),
      analyser_(clip_.sampleRate) {}

AudioFeatures AudioFileInput::at(double seconds) {
  if (!std::isfinite(seconds)) return analyser_.take();
  // The samples strictly before `seconds`: ceil(x), but a time within a millionth of a sample of
  // one counts as on it, so times reached by different sums of steps land on the same sample.
  const double x = (seconds - start_) * clip_.sampleRate;
  if (x <= 0.0) return analyser_.take();
  const double nearest = std::round(x);
  const double count = std::abs(x - nearest) < 1e-6 ? nearest : std::ceil(x);
  const auto end = uint64_t(std::min(count, 9.0e18));

  const uint64_t now = analyser_.streamPosition();
  const auto catchUp = uint64_t(kCatchUpSeconds * clip_.sampleRate);
  if (end > now && end - now > catchUp) {
    // Restart on the hop grid the analysis would have had from 0, so bands and level match it.
    const uint64_t from = (end - catchUp) / AudioAnalyser::kHop * AudioAnalyser::kHop;
    analyser_ = AudioAnalyser(clip_.sampleRate, from);
  }
  feed(end);
  return analyser_.take();
}

void AudioFileInput::feed(uint64_t end) {
  const uint64_t frames = mono_.size();
  scratch_.resize(4096);
  for (uint64_t at = analyser_.streamPosition(); at < end;) {
    const size_t n = size_t(std::min<uint64_t>(scratch_.size(), end - at));
    for (size_t i = 0; i < n; ++i) {
      const uint64_t f = at + i;
      scratch_[i] = loop_ ? mono_[size_t(f % frames)] : (f < frames ? mono_[size_t(f)] : 0.0f);
    }
    analyser_.push(std::span<const float>(scratch_.data(), n));
    at += n;
  }
}

}  // namespace vitrine::live
