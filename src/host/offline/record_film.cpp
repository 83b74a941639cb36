// record --out NAME.mp4|.mov|.mkv: the film itself, no frame files. Frames render as record.cpp renders
// them (fixed steps, --spp samples averaged) and go straight into FFmpeg's encoder; the scene's sound
// (and the --audio-in music) is muxed in once the last frame is done. Nothing named like the target
// exists until the film is whole: an error or Ctrl-C leaves the target as it was and no temporary.
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/output_path.h"
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
  const StopOnSignal stop;  // caught from before the temporary exists until it is gone
  // FFmpeg's encoder is opened before the GPU starts: a codec this FFmpeg lacks stops the run at once.
  film::VideoEncoder encoder(target, format, config.size.width, config.size.height, options.fps);

  gpu::Instance instance({options.validation, {}});
  gpu::Device device(instance, {options.device});
  RecordInputs inputs(options, config);
  {
    Offscreen offscreen(device, config);
    RecordProgress progress(frames);
    for (uint32_t frame = 0; frame < frames; ++frame) {
      stop.check(fmt::format("after {} of {} frames; no film written, {} left as it was.", frame, frames,
                             target.string()));
      encoder.addFrame(renderFrame(offscreen, options.spp));
      progress.update(frame + 1, frame + 1);
    }
  }
  if (inputs.events) inputs.events->close();
  const std::vector<float> samples = filmSound(inputs.sound, inputs.live.get(), options.time, double(frames) / options.fps);
  stop.check(fmt::format("before the film was written; {} left as it was.", target.string()));
  encoder.finish(samples);
  std::printf("recorded %u frames into %s (%ux%u, %s %s in %s, %.6g fps, %u samples a frame, %s, scene %s) on %s\n",
              frames, target.c_str(), config.size.width, config.size.height, std::string(film::codecName(format.codec)).c_str(),
              format.pixelFormat.c_str(), format.muxer.c_str(), options.fps, options.spp,
              samples.empty() ? "no sound" : fmt::format("sound as {}", format.audioEncoder).c_str(),
              options.scene.c_str(), device.properties().deviceName);
  if (instance.validationMessages() > 0) {
    std::fprintf(stderr, "%d validation messages: failing.\n", instance.validationMessages());
    return 3;
  }
  return 0;
}

}  // namespace vitrine::host
