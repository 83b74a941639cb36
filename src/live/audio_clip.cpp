#include "live/audio_clip.h"

#include <fmt/format.h>
#include <samplerate.h>
#include <sndfile.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <string>

#include "core/bounded_file.h"
#include "core/error.h"

namespace vitrine::live {

size_t AudioClip::frames() const { return channels > 0 ? samples.size() / size_t(channels) : 0; }

double AudioClip::seconds() const { return sampleRate > 0 ? double(frames()) / sampleRate : 0.0; }

namespace {

constexpr double kOutputRate = 48000.0;

// libsndfile's messages end in a full stop; ours add to them.
std::string reasonOf(SNDFILE* file) {
  std::string reason = sf_strerror(file);
  while (!reason.empty() && (reason.back() == '.' || reason.back() == ' ' || reason.back() == '\n'))
    reason.pop_back();
  return reason;
}

struct SndfileCloser {
  void operator()(SNDFILE* file) const { sf_close(file); }
};

}  // namespace

AudioClip readAudioFile(const std::filesystem::path& path) {
  // Opened through the bounded-file gate: libsndfile handed a fifo waits for a writer forever.
  int fd = -1;
  try {
    fd = BoundedFile(path, kMaxClipFileBytes).release();
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("Cannot read the sound file {}: {}", path.string(), refused.why));
  }
  SF_INFO info{};
  std::unique_ptr<SNDFILE, SndfileCloser> file(sf_open_fd(fd, SFM_READ, &info, /*close_desc (on failure too)=*/SF_TRUE));
  if (!file) throw Error(fmt::format("Cannot read the sound file {}: {}", path.string(), reasonOf(nullptr)));
  if (info.channels < 1 || info.channels > kMaxClipChannels)
    throw Error(fmt::format("Cannot use the sound file {}: it has {} channels, and 1 to {} are supported",
                            path.string(), info.channels, kMaxClipChannels));
  if (info.samplerate < kMinClipRate || info.samplerate > kMaxClipRate)
    throw Error(fmt::format("Cannot use the sound file {}: its sample rate of {} Hz is not from {} to {} Hz",
                            path.string(), info.samplerate, kMinClipRate, kMaxClipRate));

  AudioClip clip;
  clip.sampleRate = info.samplerate;
  clip.channels = info.channels;
  const auto channels = size_t(info.channels);
  // A frame count over the limits is refused before anything is read; one libsndfile cannot know
  // beforehand (a stream) is checked as it is read.
  const auto maxFrames =
      std::min(kMaxClipSamples / channels, size_t(std::floor(kMaxClipSeconds * double(info.samplerate))));
  const auto tooLong = [&] {
    return Error(fmt::format("Cannot use the sound file {}: it is longer than {} minutes or {} samples", path.string(),
                             kMaxClipSeconds / 60.0, kMaxClipSamples));
  };
  if (info.frames > 0 && info.frames != SF_COUNT_MAX && uint64_t(info.frames) > maxFrames) throw tooLong();
  if (info.frames > 0 && info.frames != SF_COUNT_MAX) clip.samples.reserve(size_t(info.frames) * channels);

  constexpr size_t kChunkFrames = 65536;
  std::vector<float> chunk(kChunkFrames * channels);
  size_t frames = 0;
  for (;;) {
    const sf_count_t got = sf_readf_float(file.get(), chunk.data(), sf_count_t(kChunkFrames));
    if (got <= 0) break;
    frames += size_t(got);
    if (frames > maxFrames) throw tooLong();
    clip.samples.insert(clip.samples.end(), chunk.begin(), chunk.begin() + got * sf_count_t(channels));
  }
  if (sf_error(file.get()) != SF_ERR_NO_ERROR)
    throw Error(fmt::format("Cannot read the sound file {}: {}", path.string(), reasonOf(file.get())));
  if (frames == 0) throw Error(fmt::format("Cannot use the sound file {}: it holds no samples", path.string()));
  return clip;
}

std::vector<float> monoMix(const AudioClip& clip) {
  const size_t frames = clip.frames(), channels = size_t(std::max(clip.channels, 0));
  std::vector<float> mono(frames);
  for (size_t f = 0; f < frames; ++f) {
    float sum = 0;
    for (size_t c = 0; c < channels; ++c) sum += clip.samples[f * channels + c];
    mono[f] = sum / float(channels);
  }
  return mono;
}

namespace {

void checkPlayable(const AudioClip& clip, double startSeconds) {
  if (!std::isfinite(startSeconds) || std::abs(startSeconds) > 1e9)
    throw Error(fmt::format("Cannot take sound from {} s: the start must be a finite number of seconds", startSeconds));
  if (!(clip.sampleRate >= kMinClipRate && clip.sampleRate <= kMaxClipRate))
    throw Error(fmt::format("Cannot resample sound at {} Hz: the rate must be from {} to {} Hz", clip.sampleRate,
                            kMinClipRate, kMaxClipRate));
  if (clip.channels < 0 || (clip.channels == 0 && !clip.samples.empty()) ||
      (clip.channels > 0 && clip.samples.size() % size_t(clip.channels) != 0))
    throw Error(fmt::format("Cannot play a clip of {} samples in {} channels: they are not whole frames",
                            clip.samples.size(), clip.channels));
}

}  // namespace

// libsamplerate's sinc filter starts from silence, so it is primed with `margin` clip frames before the
// start, whose output is thrown away. The margin is a whole number of rate periods (lcm / rate clip
// frames give lcm / 48000 output frames), so the output frame that lines up with the start is an exact
// index into what comes out; it is at least 1024 output frames' worth, so a downsampling filter's longer
// reach is covered too.
struct Stereo48kStream::Resampler {
  struct Delete {
    void operator()(SRC_STATE* converter) const { src_delete(converter); }
  };
  std::unique_ptr<SRC_STATE, Delete> state;
  double ratio = 1.0;
  int64_t skip = 0;           // output frames of the priming still to throw away
  std::vector<float> input;   // clip frames read ahead as stereo pairs, from `used` on not yet taken
  size_t used = 0;
  std::vector<float> primed;  // the priming's output, thrown away
};

Stereo48kStream::Stereo48kStream(const AudioClip& clip, double startSeconds, bool loop)
    : clip_(clip), loop_(loop) {
  checkPlayable(clip, startSeconds);
  nextFrame_ = std::llround(startSeconds * clip.sampleRate);
  if (clip.sampleRate == kOutputRate) return;
  const auto rate = int64_t(std::llround(clip.sampleRate)), out48 = int64_t(kOutputRate);
  const int64_t gcd = std::gcd(rate, out48), periodIn = rate / gcd, periodOut = out48 / gcd;
  resampler_ = std::make_unique<Resampler>();
  resampler_->ratio = kOutputRate / clip.sampleRate;
  const auto minMargin = int64_t(std::ceil(1024.0 / std::min(resampler_->ratio, 1.0)));
  const int64_t periods = (minMargin + periodIn - 1) / periodIn;
  nextFrame_ -= periods * periodIn;
  resampler_->skip = periods * periodOut;
  int error = 0;
  resampler_->state.reset(src_new(SRC_SINC_MEDIUM_QUALITY, 2, &error));
  if (!resampler_->state)
    throw Error(fmt::format("Cannot resample sound from {} Hz to 48000 Hz: {}", clip.sampleRate, src_strerror(error)));
}

Stereo48kStream::~Stereo48kStream() = default;

void Stereo48kStream::frameAt(int64_t i, float* pair) const {
  const auto frames = int64_t(clip_.frames());
  if (loop_ && frames > 0) i = ((i % frames) + frames) % frames;
  if (i < 0 || i >= frames) {
    pair[0] = pair[1] = 0.0f;
    return;
  }
  const auto channels = size_t(clip_.channels);
  const float* f = clip_.samples.data() + size_t(i) * channels;
  for (size_t c = 0; c < 2; ++c) {
    const float s = f[std::min(c, channels - 1)];
    pair[c] = std::isfinite(s) ? s : 0.0f;
  }
}

void Stereo48kStream::next(float* out, size_t frames) {
  if (clip_.frames() == 0) {
    std::fill_n(out, frames * 2, 0.0f);
    return;
  }
  if (!resampler_) {
    for (size_t j = 0; j < frames; ++j) frameAt(nextFrame_++, out + 2 * j);
    return;
  }
  Resampler& r = *resampler_;
  while (r.skip > 0) {
    r.primed.resize(size_t(std::min<int64_t>(r.skip, 4096)) * 2);
    resampled(r.primed.data(), r.primed.size() / 2);
    r.skip -= int64_t(r.primed.size() / 2);
  }
  resampled(out, frames);
}

// Exactly `frames` frames out of the filter, reading the clip ahead as it asks for more.
void Stereo48kStream::resampled(float* out, size_t frames) {
  constexpr size_t kReadAhead = 4096;
  Resampler& r = *resampler_;
  while (frames > 0) {
    if (r.used * 2 == r.input.size()) {
      r.input.resize(kReadAhead * 2);
      for (size_t i = 0; i < kReadAhead; ++i) frameAt(nextFrame_++, r.input.data() + 2 * i);
      r.used = 0;
    }
    SRC_DATA data{};
    data.data_in = r.input.data() + 2 * r.used;
    data.input_frames = long(r.input.size() / 2 - r.used);
    data.data_out = out;
    data.output_frames = long(frames);
    data.src_ratio = r.ratio;
    data.end_of_input = 0;
    if (const int error = src_process(r.state.get(), &data))
      throw Error(fmt::format("Cannot resample sound from {} Hz to 48000 Hz: {}", clip_.sampleRate, src_strerror(error)));
    if (data.input_frames_used == 0 && data.output_frames_gen == 0)  // never with input to take; a guard all the same
      throw Error(fmt::format("Cannot resample sound from {} Hz to 48000 Hz: the filter stopped", clip_.sampleRate));
    r.used += size_t(data.input_frames_used);
    out += 2 * size_t(data.output_frames_gen);
    frames -= size_t(data.output_frames_gen);
  }
}

std::vector<float> stereo48k(const AudioClip& clip, double startSeconds, double seconds, bool loop) {
  if (!(seconds >= 0.0 && seconds <= kMaxClipSeconds))
    throw Error(fmt::format("Cannot take {} s of sound: the length must be from 0 to {} s", seconds,
                            kMaxClipSeconds));
  Stereo48kStream stream(clip, startSeconds, loop);
  std::vector<float> out(size_t(std::llround(seconds * kOutputRate)) * 2);
  stream.next(out.data(), out.size() / 2);
  return out;
}

}  // namespace vitrine::live
