#pragma once
// A film encoded as its frames arrive, through FFmpeg's libraries: frames go into a hidden temporary
// beside the target (video only, in the target's container); finish() adds the sound, known only once
// the film has been rendered, and only then does the target's name appear, by a rename. A film that is
// never finished (an error, Ctrl-C, a destructor reached first) leaves its target as it was and no
// temporary behind.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>

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

  // The next frame, as linear light (a render, an EXR): put on the sRGB curve exactly as the PNG writer
  // does (srgb8, or srgb16 for a 10-bit film). Alpha is dropped: a film is opaque.
  void addFrame(const ImageRgba& linear);
  // The next frame, as display values already (a PNG read back): its bytes as they are.
  void addFrame(const Picture& srgb);
  uint32_t frames() const;

  // Ends the video and writes the film: with sound (interleaved stereo at 48 kHz, cut or padded with
  // silence to the film's length), the video's packets are copied beside the encoded sound into a
  // second temporary, interleaved by time; without, the video-only temporary is the film. Renamed over
  // the target last. Throws vitrine::Error, the target left as it was.
  void finish(std::span<const float> stereo48k);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vitrine::film
