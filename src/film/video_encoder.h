#pragma once
// A film encoded as its frames and its sound arrive, through FFmpeg's libraries, into a hidden temporary
// beside the target that grows as the film is made: video and sound packets interleaved by time as they
// come, so memory stays flat however long the film. Only once the film is finished does the target's
// name appear, by a rename. A film that is never finished (an error, Ctrl-C, a destructor reached
// first) leaves its target as it was and no temporary behind.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

#include "film/film_format.h"
#include "image/image.h"
#include "image/image_io.h"

namespace vitrine::film {

class VideoEncoder {
 public:
  // Opens FFmpeg's encoder for `format` and the temporary. Throws vitrine::Error naming the target:
  // an encoder this FFmpeg lacks, a folder that cannot be written.
  VideoEncoder(const std::filesystem::path& target, const FilmFormat& format, uint32_t width, uint32_t height,
               double fps);
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // Gives the film a sound track, before its first frame: 48 kHz stereo, given with addSound as the
  // film goes. Throws vitrine::Error after the first frame, or naming an encoder this FFmpeg lacks.
  void addSoundTrack();
  bool hasSoundTrack() const;

  // The next frame, as linear light (a render, an EXR): put on the sRGB curve exactly as the PNG writer
  // does (srgb8, or srgb16 for a 10-bit film). Alpha is dropped: a film is opaque.
  void addFrame(const ImageRgba& linear);
  // The next frame, as display values already (a PNG read back): its bytes as they are.
  void addFrame(const Picture& srgb);
  // The next frame, as display values already laid out as layout() says (shaders/host/film_pack.comp
  // packs them on the GPU): converted and encoded with no other copy. The bytes are read only during
  // the call.
  void addDisplay(std::span<const std::byte> bytes);
  DisplayLayout layout() const;
  // The encoder that took the film, and why the hardware ones before it did not ("libx264; h264_nvenc:
  // Cannot load libcuda.so.1; h264_vaapi: no render node in /dev/dri"). An h264 or hevc film in yuv420p
  // and limited range takes NVENC, then VAAPI, where one opens, and the software encoder otherwise.
  const std::string& encoderChoice() const;
  uint32_t frames() const;

  // The sound's next stretch, interleaved stereo at 48 kHz, following the last: given as the film goes
  // (a little behind its frames is fine, the muxer holds what it must to interleave them).
  void addSound(std::span<const float> stereo48k);

  // Ends the film and renames it over the target: the sound, if it has a track, cut or padded with
  // silence to exactly round(frames / fps x 48000) frames, so both streams end together. Throws
  // vitrine::Error, the target left as it was.
  void finish();

  // Seconds spent so far in each stage: the conversion into the encoder's pixel format, the video
  // encoder and muxer, the sound encoder.
  struct StageTimes {
    double convert = 0.0, encode = 0.0, sound = 0.0;
  };
  StageTimes times() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vitrine::film
