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

std::vector<float> stereo48k(const AudioClip& clip, double startSeconds, double seconds, bool loop) {
  if (!std::isfinite(startSeconds) || std::abs(startSeconds) > 1e9)
    throw Error(fmt::format("Cannot take sound from {} s: the start must be a finite number of seconds", startSeconds));
  if (!(seconds >= 0.0 && seconds <= kMaxClipSeconds))
    throw Error(fmt::format("Cannot take {} s of sound: the length must be from 0 to {} s", seconds,
                            kMaxClipSeconds));
  if (!(clip.sampleRate >= kMinClipRate && clip.sampleRate <= kMaxClipRate))
    throw Error(fmt::format("Cannot resample sound at {} Hz: the rate must be from {} to {} Hz", clip.sampleRate,
                            kMinClipRate, kMaxClipRate));
  if (clip.channels < 0 || (clip.channels == 0 && !clip.samples.empty()) ||
      (clip.channels > 0 && clip.samples.size() % size_t(clip.channels) != 0))
    throw Error(fmt::format("Cannot play a clip of {} samples in {} channels: they are not whole frames",
                            clip.samples.size(), clip.channels));

  const auto outFrames = size_t(std::llround(seconds * kOutputRate));
  std::vector<float> out(outFrames * 2, 0.0f);
  const auto frames = int64_t(clip.frames());
  if (outFrames == 0 || frames == 0) return out;

  const auto channels = size_t(clip.channels);
  // Frame `i` of the clip on the clip's own time line, as a stereo pair: silence outside the clip
  // unless it loops.
  const auto frameAt = [&](int64_t i, float* pair) {
    if (loop) i = ((i % frames) + frames) % frames;
    if (i < 0 || i >= frames) {
      pair[0] = pair[1] = 0.0f;
      return;
    }
    const float* f = clip.samples.data() + size_t(i) * channels;
    for (size_t c = 0; c < 2; ++c) {
      const float s = f[std::min(c, channels - 1)];
      pair[c] = std::isfinite(s) ? s : 0.0f;
    }
  };
  const auto first = std::llround(startSeconds * clip.sampleRate);

  if (clip.sampleRate == kOutputRate) {
    for (size_t j = 0; j < outFrames; ++j) frameAt(first + int64_t(j), out.data() + 2 * j);
    return out;
  }

  // libsamplerate's sinc filter starts from silence and ends on it, so the span is converted with
  // clip before and after it (`margin` clip frames each side, at least 1024 output frames' worth,
  // so a downsampling filter's longer reach is covered too). The leading margin is a whole number of
  // rate periods (lcm / rate clip frames give lcm / 48000 output frames), so the output frame that
  // lines up with `first` is an exact index into the converted block.
  const auto rate = int64_t(std::llround(clip.sampleRate)), out48 = int64_t(kOutputRate);
  const int64_t gcd = std::gcd(rate, out48), periodIn = rate / gcd, periodOut = out48 / gcd;
  const double ratio = kOutputRate / clip.sampleRate;
  const auto minMargin = int64_t(std::ceil(1024.0 / std::min(ratio, 1.0)));
  const int64_t periods = (minMargin + periodIn - 1) / periodIn;
  const int64_t margin = periods * periodIn, marginOut = periods * periodOut;
  const auto spanIn = int64_t(std::ceil(double(outFrames) / ratio)) + 2 * margin;

  std::vector<float> in(size_t(spanIn) * 2);
  for (int64_t i = 0; i < spanIn; ++i) frameAt(first - margin + i, in.data() + 2 * i);
  std::vector<float> converted((size_t(marginOut) + outFrames + size_t(std::ceil(double(margin) * ratio)) + 64) * 2);
  SRC_DATA data{};
  data.data_in = in.data();
  data.input_frames = long(spanIn);
  data.data_out = converted.data();
  data.output_frames = long(converted.size() / 2);
  data.src_ratio = ratio;
  data.end_of_input = 1;
  if (const int error = src_simple(&data, SRC_SINC_MEDIUM_QUALITY, 2))
    throw Error(fmt::format("Cannot resample sound from {} Hz to 48000 Hz: {}", clip.sampleRate, src_strerror(error)));
  const auto available = std::max<int64_t>(0, int64_t(data.output_frames_gen) - marginOut);
  const auto copied = size_t(std::min<int64_t>(available, int64_t(outFrames)));
  std::copy_n(converted.begin() + marginOut * 2, copied * 2, out.begin());
  return out;
}

}  // namespace vitrine::live
