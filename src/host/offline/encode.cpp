// encode FOLDER --out NAME.mp4|.mov|.mkv: a sequence `vitrine record` wrote (frame_NNNNNN.exr or .png, its
// size, rate and format in record.json) and its audio.wav, if any, into one film, encoded as record --out
// encodes: EXR frames go through the PNG writer's sRGB conversion, PNG frames' bytes are used as they are,
// so a film from either equals the one record --out makes. A folder missing a frame, or holding one of
// another size, is refused, naming the frame.
#include "core/atomic_file.h"
#include "core/error.h"
#include "film/video_encoder.h"
#include "host/modes.h"
#include "host/offline/record_manifest.h"
#include "host/offline/record_shared.h"
#include "core/stop_signal.h"
#include "image/image_io.h"
#include "live/audio_clip.h"

#include <fmt/format.h>

#include <cstdio>
#include <limits>
#include <optional>
#include <regex>

namespace vitrine::host {
namespace {

std::string frameName(uint32_t frame, const std::string& format) { return fmt::format("frame_{:06d}.{}", frame, format); }

// How many frames the film has: one more than the highest numbered frame in the folder. Throws,
// naming the first gap, unless every frame before it is there too.
uint32_t countFrames(const std::filesystem::path& folder, const std::string& format) {
  const std::regex pattern("frame_([0-9]{6})\\." + format);
  std::optional<uint32_t> last;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    std::smatch match;
    const std::string name = entry.path().filename().string();
    if (std::regex_match(name, match, pattern)) last = std::max(last.value_or(0), uint32_t(std::stoul(match[1].str())));
  }
  if (!last)
    throw Error(fmt::format("{} holds no {} frames (frame_000000.{} ...), which its record.json names.", folder.string(),
                            format, format));
  for (uint32_t frame = 0; frame <= *last; ++frame)
    if (!std::filesystem::is_regular_file(folder / frameName(frame, format), ec))
      throw Error(fmt::format("{} is missing {} (the film runs to {}); record it again (vitrine record resumes "
                              "where frames are missing) before encoding.",
                              folder.string(), frameName(frame, format), frameName(*last, format)));
  return *last + 1;
}

void checkFrameSize(const std::filesystem::path& path, uint32_t width, uint32_t height, const RecordManifest& recorded) {
  if (width != recorded.width || height != recorded.height)
    throw Error(fmt::format("{} is {}x{}, not {}x{} as the film's record.json says; every frame of a film has one size.",
                            path.string(), width, height, recorded.width, recorded.height));
}

}  // namespace

int runEncode(const Options& options) {
  const std::filesystem::path folder = options.sequence, target = options.out;
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec))
    throw Error(fmt::format("Cannot encode {}: it is not a folder.", folder.string()));
  const RecordManifest recorded = readManifest(folder);
  if (recorded.format != "exr" && recorded.format != "png")
    throw Error(fmt::format("{}'s record.json names frames of format '{}'; vitrine record writes exr or png.",
                            folder.string(), recorded.format));
  const film::FilmFormat format = film::resolveFilm(target, options.film, recorded.width, recorded.height);
  const uint32_t frames = countFrames(folder, recorded.format);
  const double seconds = double(frames) / recorded.fps;

  // The sound, the film's length exactly; a sound track longer than the frames says the last are missing.
  std::vector<float> samples;
  const std::filesystem::path wav = folder / "audio.wav";
  if (std::filesystem::exists(wav, ec)) {
    const live::AudioClip clip = live::readAudioFile(wav);
    if (clip.seconds() > seconds + 1.0 / recorded.fps)
      throw Error(fmt::format("{} lasts {:.3f} s, but the frames stop at {} ({:.3f} s): {} and after are missing; "
                              "record them before encoding.",
                              wav.string(), clip.seconds(), frameName(frames - 1, recorded.format), seconds,
                              frameName(frames, recorded.format)));
    samples = live::stereo48k(clip, 0.0, seconds);
  }

  const std::filesystem::path targetFolder = target.has_parent_path() ? target.parent_path() : ".";
  checkWritableFolder(targetFolder);
  for (const auto& stale : removeStaleTemporaries(targetFolder))
    std::fprintf(stderr, "vitrine: removed %s, left by a writer that died\n", stale.filename().c_str());
  const StopOnSignal stop;
  film::VideoEncoder encoder(target, format, recorded.width, recorded.height, recorded.fps);
  RecordProgress progress(frames);
  const bool png = recorded.format == "png";
  for (uint32_t frame = 0; frame < frames; ++frame) {
    stop.check(fmt::format("after {} of {} frames; no film written, {} left as it was.", frame, frames,
                           target.string()));
    const std::filesystem::path path = folder / frameName(frame, recorded.format);
    if (png) {
      // No limit on the size: readPicture would scale a larger frame down.
      const Picture picture = readPicture(path, std::numeric_limits<uint32_t>::max());
      checkFrameSize(path, picture.width, picture.height, recorded);
      encoder.addFrame(picture);
    } else {
      const ImageRgba image = readImage(path);
      checkFrameSize(path, image.width, image.height, recorded);
      encoder.addFrame(image);
    }
    progress.update(frame + 1, frame + 1);
  }
  encoder.finish(samples);
  std::printf("encoded %u frames of %s into %s (%ux%u, %s %s in %s, %.6g fps, %s)\n", frames, folder.c_str(),
              target.c_str(), recorded.width, recorded.height, std::string(film::codecName(format.codec)).c_str(),
              format.pixelFormat.c_str(), format.muxer.c_str(), recorded.fps,
              samples.empty() ? "no sound" : fmt::format("sound as {}", format.audioEncoder).c_str());
  return 0;
}

}  // namespace vitrine::host
