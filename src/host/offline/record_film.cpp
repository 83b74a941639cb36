// record --out NAME.mp4|.mov|.mkv: the film itself, no frame files. Frames render as record.cpp renders
// them (fixed steps, --spp samples averaged) and go straight into FFmpeg's encoder; the scene's sound
// (and the --audio-in music) goes in beside them as the film goes, rendered a stretch at a time half a
// second behind the frames (FilmSound), so the film streams to disk and memory stays flat however long
// it is. Nothing named like the target exists until the film is whole: an error or Ctrl-C leaves the
// target as it was and no temporary.
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/output_path.h"
#include "core/resident_memory.h"
#include "film/video_encoder.h"
#include "host/event_log.h"
#include "host/modes.h"
#include "host/offline/record_shared.h"
#include "core/stop_signal.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>

namespace vitrine::host {

int runRecordFilm(const Options& options) {
  const std::filesystem::path target = options.out;
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  checkWritable(target);
  checkWritableFolder(folder);  // a read-only mount or a full disk is found before anything renders
  for (const auto& stale : removeStaleTemporaries(folder))
    std::fprintf(stderr, "vitrine: removed %s, left by a writer that died\n", stale.filename().c_str());

  OffscreenConfig config = recordConfig(options);
  const film::FilmFormat format = film::resolveFilm(target, options.film, config.size.width, config.size.height);
  const uint32_t frames = std::max(1u, uint32_t(std::lround(options.seconds * options.fps)));
  const double seconds = double(frames) / options.fps;
  const StopOnSignal stop;  // caught from before the temporary exists until it is gone
  // FFmpeg's encoder is opened before the GPU starts: a codec this FFmpeg lacks stops the run at once.
  film::VideoEncoder encoder(target, format, config.size.width, config.size.height, options.fps);

  gpu::Instance instance({options.validation, {}});
  gpu::Device device(instance, {options.device});
  RecordInputs inputs(options, config);
  std::optional<FilmSound> sound;
  ResidentByFrames resident(frames);
  {
    Offscreen offscreen(device, config);
    RecordProgress progress(frames);
    for (uint32_t frame = 0; frame < frames; ++frame) {
      stop.check(fmt::format("after {} of {} frames; no film written, {} left as it was.", frame, frames,
                             target.string()));
      resident.before(frame);
      const ImageRgba picture = renderFrame(offscreen, options.spp);
      // The streams are all there before the first packet: the film has sound when its scene made some
      // in its first frame (bloom's drone starts with it) or music plays.
      if (frame == 0 && FilmSound::any(inputs.sound, inputs.live.get())) {
        encoder.addSoundTrack();
        sound.emplace(inputs.sound, inputs.live.get(), options.time, seconds);
      }
      encoder.addFrame(picture);
      if (sound) encoder.addSound(sound->next(FilmSound::behind(double(frame + 1) / options.fps)));
      progress.update(frame + 1, frame + 1);
    }
  }  // the scene is gone: its last sounds (bloom's drone stopping) are posted
  if (inputs.events) inputs.events->close();
  stop.check(fmt::format("before the film was written; {} left as it was.", target.string()));
  if (sound) encoder.addSound(sound->next(sound->frames()));
  else if (inputs.sound.commandCount() > 0)
    std::fprintf(stderr, "vitrine: %s made its first sound after its first frame; the film has none (record into a "
                 "folder for its audio.wav)\n", options.scene.c_str());
  if (sound && sound->late() > 0)
    std::fprintf(stderr, "vitrine: %zu of %s's sounds came over %.1f s after their time and play late\n",
                 sound->late(), options.scene.c_str(), FilmSound::kSoundLag);
  encoder.finish();
  if (const std::string line = resident.line(); !line.empty()) std::printf("%s\n", line.c_str());
  std::printf("recorded %u frames into %s (%ux%u, %s %s in %s, %.6g fps, %u samples a frame, %s, scene %s) on %s\n",
              frames, target.c_str(), config.size.width, config.size.height, std::string(film::codecName(format.codec)).c_str(),
              format.pixelFormat.c_str(), format.muxer.c_str(), options.fps, options.spp,
              sound ? fmt::format("sound as {}", format.audioEncoder).c_str() : "no sound",
              options.scene.c_str(), device.properties().deviceName);
  if (instance.validationMessages() > 0) {
    std::fprintf(stderr, "%d validation messages: failing.\n", instance.validationMessages());
    return 3;
  }
  return 0;
}

}  // namespace vitrine::host
