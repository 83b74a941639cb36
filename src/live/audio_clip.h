#pragma once
// A sound file in memory: read once by libsndfile, then analysed as live input or played as a
// film's sound track.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace vitrine::live {

struct AudioClip {
  double sampleRate = 48000.0;
  int channels = 0;
  std::vector<float> samples;  // interleaved

  size_t frames() const;
  double seconds() const;
};

// The limits readAudioFile enforces: a longer file is refused before it fills memory.
inline constexpr double kMaxClipSeconds = 30.0 * 60.0;
inline constexpr size_t kMaxClipSamples = size_t(1) << 28;  // 1 GiB of floats
inline constexpr int kMaxClipChannels = 8;
// The largest sound file read: the longest clip as 32-bit samples, with room for a header.
inline constexpr uintmax_t kMaxClipFileBytes = uintmax_t(kMaxClipSamples) * 4 + (1u << 20);
inline constexpr double kMinClipRate = 1000.0, kMaxClipRate = 768000.0;

// Reads whatever Debian 12's libsndfile reads (WAV, FLAC, Ogg Vorbis and Opus, MP3, AIFF, ...) as
// floats in [-1, 1] (integer formats scaled by libsndfile). Throws vitrine::Error naming the file and
// libsndfile's reason when it cannot be read, and refuses a file with no samples, 0 or more than
// kMaxClipChannels channels, a sample rate outside kMinClipRate..kMaxClipRate, or more than
// kMaxClipSeconds or kMaxClipSamples.
AudioClip readAudioFile(const std::filesystem::path& path);

// The average of the channels, one sample per frame.
std::vector<float> monoMix(const AudioClip& clip);

// `seconds` of the clip from `startSeconds` (rounded to the nearest frame of the clip) as 48 kHz
// interleaved stereo: mono duplicated, more than 2 channels: the first two. Other rates are
// resampled by libsamplerate (SRC_SINC_MEDIUM_QUALITY, one call over the whole span with the
// filter primed from the clip before it: deterministic, whatever span is asked for); 48 kHz is copied
// as it is. Past the clip's end (and before its start): silence, or the clip again when `loop`.
// Samples that are not finite play as 0. Exactly round(seconds x 48000) frames. Throws vitrine::Error
// for a non-finite start, a negative or non-finite length (or one over kMaxClipSeconds), or a clip
// whose rate is outside kMinClipRate..kMaxClipRate or whose samples are not whole frames.
std::vector<float> stereo48k(const AudioClip& clip, double startSeconds, double seconds, bool loop = false);

// The same, a stretch at a time, for as long as it is asked: a film's music written as its frames are,
// its state (libsamplerate's filter) carried from one stretch to the next, so the stretches together
// are sample for sample stereo48k's over their whole span, wherever they end. Throws vitrine::Error as
// stereo48k does for the start or the clip. The clip must outlive it.
class Stereo48kStream {
 public:
  Stereo48kStream(const AudioClip& clip, double startSeconds, bool loop = false);
  ~Stereo48kStream();
  Stereo48kStream(const Stereo48kStream&) = delete;
  Stereo48kStream& operator=(const Stereo48kStream&) = delete;

  // The next `frames` frames, interleaved stereo, into out[0 .. 2 x frames).
  void next(float* out, size_t frames);

 private:
  void frameAt(int64_t i, float* pair) const;  // the clip's frame i as a stereo pair (silence outside)
  void resampled(float* out, size_t frames);
  struct Resampler;
  const AudioClip& clip_;
  bool loop_;
  int64_t nextFrame_;  // the clip's next frame to read
  std::unique_ptr<Resampler> resampler_;  // none at 48 kHz
};

}  // namespace vitrine::live
