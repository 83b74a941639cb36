// record --out NAME.mp4|.mov|.mkv: the film itself, no frame files. Frames render as record.cpp renders
// them (fixed steps, --spp samples averaged) and go straight into FFmpeg's encoder; the scene's sound
// (and the --audio-in music) goes in beside them as the film goes, rendered a stretch at a time half a
// second behind the frames (FilmSound), so the film streams to disk and memory stays flat however long
// it is. Nothing named like the target exists until the film is whole: an error or Ctrl-C leaves the
// target as it was and no temporary.
//
// The frames go through a pipeline: the GPU packs each rendered frame into the encoder's bytes and
// copies them into one of a few slots (FilmFrames), and the encoder converts and encodes them on its
// own thread (EncoderThread) while the next frames render. A film of several samples a frame averages
// them on the CPU as before and hands the average to the same thread. VITRINE_FILM_STAGES=1 prints
// where the time went, stage by stage.
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/output_path.h"
#include "core/resident_memory.h"
#include "film/video_encoder.h"
#include "host/event_log.h"
#include "host/modes.h"
#include "host/offline/encoder_thread.h"
#include "host/offline/film_frames.h"
#include "host/offline/record_shared.h"
#include "core/stop_signal.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

namespace vitrine::host {
namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

constexpr uint32_t kSlots = 4;    // frames between the GPU and the encoder (film_frames.h)
constexpr size_t kQueued = 8;     // jobs waiting for the encoder's thread: a slot's frame, a stretch of sound

// Where a film's time went, for VITRINE_FILM_STAGES=1: milliseconds a frame in each stage.
struct FilmStages {
  double render = 0.0;  // simulation, recording, the GPU's frame, waited for
  double pack = 0.0;    // recording and submitting the packing pass and copy
  double sound = 0.0;   // the scene's sound rendered
  bool gpuPacked = false;

  static bool wanted() {
    const char* env = std::getenv("VITRINE_FILM_STAGES");
    return env && std::string(env) == "1";
  }
  void print(uint32_t frames, double wall, const film::VideoEncoder::StageTimes& encoder, const FilmFrames* packed,
             double postWaits, const std::string& choice) const {
    const double n = std::max(1u, frames) / 1000.0;
    std::printf("film stages (ms a frame): render %.2f, pack %.2f, sound %.2f, waiting for a slot %.2f, waiting for the "
                "encoder's queue %.2f | encoder thread: waiting for the copy %.2f, convert %.2f, encode %.2f, sound "
                "encode %.2f | %u frames in %.2f s (%.1f frames/s), %s, encoded with %s\n",
                render / n, pack / n, sound / n, packed ? packed->slotWaits() / n : 0.0, postWaits / n,
                packed ? packed->copyWaits() / n : 0.0, encoder.convert / n, encoder.encode / n, encoder.sound / n,
                frames, wall, wall > 0 ? frames / wall : 0.0,
                gpuPacked ? "packed on the GPU" : "averaged and packed on the CPU", choice.c_str());
  }
};

}  // namespace

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
  FilmStages stages;
  const auto started = Clock::now();
  double postWaits = 0.0;
  std::optional<FilmFrames> packedFrames;
  {
    Offscreen offscreen(device, config);
    // One sample a frame: packed on the GPU. Several: averaged in floats on the CPU, as a folder's are.
    stages.gpuPacked = options.spp == 1;
    if (stages.gpuPacked) packedFrames.emplace(device, config.size, encoder.layout(), kSlots);
    EncoderThread encoding(encoder, kQueued);
    RecordProgress progress(frames);
    for (uint32_t frame = 0; frame < frames; ++frame) {
      stop.check(fmt::format("after {} of {} frames; no film written, {} left as it was.", frame, frames,
                             target.string()));
      resident.before(frame);
      auto start = Clock::now();
      if (stages.gpuPacked) {
        offscreen.renderFrame();
        stages.render += secondsSince(start);
        start = Clock::now();
        const uint32_t slot = packedFrames->pack(offscreen.output());
        stages.pack += secondsSince(start);
        // The streams are all there before the first packet: the film has sound when its scene made
        // some in its first frame (bloom's drone starts with it) or music plays.
        if (frame == 0 && FilmSound::any(inputs.sound, inputs.live.get())) {
          encoder.addSoundTrack();  // the encoder's thread has had no job yet
          sound.emplace(inputs.sound, inputs.live.get(), options.time, seconds);
        }
        encoding.post([&frames = *packedFrames, slot](film::VideoEncoder* into) {
          struct Release {
            FilmFrames& frames;
            uint32_t slot;
            ~Release() { frames.release(slot); }
          } release{frames, slot};
          if (into) into->addDisplay(frames.bytes(slot));
        });
      } else {
        ImageRgba picture = renderFrame(offscreen, options.spp);
        stages.render += secondsSince(start);
        if (frame == 0 && FilmSound::any(inputs.sound, inputs.live.get())) {
          encoder.addSoundTrack();
          sound.emplace(inputs.sound, inputs.live.get(), options.time, seconds);
        }
        encoding.post([picture = std::move(picture)](film::VideoEncoder* into) {
          if (into) into->addFrame(picture);
        });
      }
      if (sound) {
        start = Clock::now();
        const std::span<const float> stretch = sound->next(FilmSound::behind(double(frame + 1) / options.fps));
        stages.sound += secondsSince(start);
        encoding.post([samples = std::vector<float>(stretch.begin(), stretch.end())](film::VideoEncoder* into) {
          if (into) into->addSound(samples);
        });
      }
      progress.update(frame + 1, frame + 1);
    }
    encoding.drain();
    postWaits = encoding.postWaits();
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
  if (FilmStages::wanted())
    stages.print(frames, secondsSince(started), encoder.times(), packedFrames ? &*packedFrames : nullptr, postWaits,
                 encoder.encoderChoice());
  packedFrames.reset();
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
