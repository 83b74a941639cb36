// record: a scene rendered offline into a numbered sequence of frames, for a film. Time advances in
// fixed steps of 1 / (fps x samples), so each frame averages `spp` samples spread over its interval
// (motion blur and anti-aliasing at once). The simulation runs from frame 0, or from the latest
// checkpoint (host/offline/checkpoint.h) at or before the first frame to write, writing only the frames asked
// for that are not already there: a run resumes where an interrupted one stopped, and frames A..B-1
// rendered on one machine are bit for bit those a whole run renders (same driver). The folder's
// record.json (host/offline/record_manifest.h) keeps a resume from mixing in another film's frames.
#include "audio/engine.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "core/printable.h"
#include "core/resident_memory.h"
#include "film/film_format.h"
#include "host/offline/checkpoint.h"
#include "host/event_log.h"
#include "host/modes.h"
#include "host/offline/offscreen.h"
#include "host/offline/record_manifest.h"
#include "host/offline/record_shared.h"
#include "image/image_io.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace vitrine::host {
namespace {

std::filesystem::path framePath(const std::filesystem::path& folder, uint32_t frame, const std::string& format) {
  return folder / fmt::format("frame_{:06d}.{}", frame, format);
}

// Frame files in the folder, and the names of those a resumed run keeps.
bool holdsFrames(const std::filesystem::path& folder) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
    if (entry.path().filename().string().starts_with("frame_")) return true;
  return false;
}

// A frame a resumed run may keep: a file that decodes whole at the film's size. Every write goes through
// a temporary renamed into place, but a frame cut short by an older version on a full disk, or copied
// in part, is rendered again rather than trusted for being there.
enum class Found { Nothing, Whole, Broken };
Found existingFrame(const std::filesystem::path& path, VkExtent2D size) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return Found::Nothing;
  return isWholeImage(path, size.width, size.height) ? Found::Whole : Found::Broken;
}

// Puts the run at the latest checkpoint at or before `firstToWrite`, if the folder holds one past frame
// 0: its sound so far and its simulation. Returns its frame. A checkpoint that cannot be trusted stops
// the run before anything is written, naming the file.
std::optional<uint32_t> resumeFromCheckpoint(Offscreen& offscreen, audio::OfflineAudio& sound,
                                             const std::filesystem::path& folder, const RecordManifest& manifest,
                                             uint32_t firstToWrite, uint32_t spp) {
  const std::string film = fingerprint(manifestText(manifest));
  const std::optional<uint32_t> at = latestCheckpointFrame(folder, firstToWrite);
  if (!at || *at == 0) return std::nullopt;
  const std::filesystem::path path = checkpointPath(folder, *at);
  const Checkpoint checkpoint = readCheckpoint(path, film);
  if (checkpoint.frame != *at || checkpoint.scene != offscreen.scene().name)
    throw Error(fmt::format("Checkpoint {} holds frame {} of {}, not what its name says: delete it.", path.string(),
                            checkpoint.frame, printable(checkpoint.scene)));
  const std::string device = offscreen.deviceName();
  if (checkpoint.device != device)
    std::fprintf(stderr, "vitrine: %s was simulated on %s, this run is on %s: its frames match a whole run only "
                 "where both devices compute alike\n", path.filename().c_str(), printable(checkpoint.device).c_str(), device.c_str());
  for (const audio::Command& command : checkpoint.sound) sound.post(command);
  try {
    offscreen.restoreSimulation(uint64_t(*at) * spp, checkpoint.simulation, manifest.values);
  } catch (const Error& e) {
    throw Error(fmt::format("Checkpoint {} does not fit this run: {}; delete it to start from an earlier one, or "
                            "from frame 0.", path.string(), e.what()));
  }
  return at;
}

}  // namespace

int runRecord(const Options& options) {
  if (film::isFilmName(options.out)) return runRecordFilm(options);  // a film, not a folder of frames
  const std::filesystem::path folder = options.out;
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (!std::filesystem::is_directory(folder, ec))
    throw Error(fmt::format("Cannot record into {}: it is not a folder that can be made.", folder.string()));
  checkWritableFolder(folder);  // a read-only folder or full disk is found before anything renders
  const uint32_t frames = std::max(1u, uint32_t(std::lround(options.seconds * options.fps)));
  const uint32_t first = options.range ? options.range->first : 0;
  const uint32_t end = options.range ? std::min(options.range->second, frames) : frames;
  if (first >= end)
    throw Error(fmt::format("--range {}:{} holds no frame of the film's {}.", first, end, frames));
  // Temporary frames of writers that were killed (SIGKILL, a power cut) never reach their rename.
  for (const auto& stale : removeStaleTemporaries(folder))
    std::fprintf(stderr, "vitrine: removed %s, left by a writer that died\n", stale.filename().c_str());

  gpu::Instance instance({options.validation, {}});
  gpu::Device device(instance, {options.device});
  OffscreenConfig config = recordConfig(options);
  RecordInputs inputs(options, config);

  uint32_t written = 0, redone = 0, saved = 0;
  std::optional<ResidentByFrames> resident;  // by the frames this run steps through, for scripts/soak
  std::optional<uint32_t> resumedAt;
  {
    Offscreen offscreen(device, config);
    RecordManifest manifest{options.scene, config.size.width, config.size.height, options.fps, options.spp,
                            options.seed, options.time, options.reducedMotion, options.format,
                            options.input.empty() && !inputs.live
                                ? std::string()
                                : fingerprint(inputs.inputText + (inputs.live ? inputs.live->fingerprintText() : "")),
                            params::snapshot(offscreen.parameters(), false)};
    std::sort(manifest.values.begin(), manifest.values.end());
    manifest.flashGuard = config.flashGuard;
    if (offscreen.renderer().hasFilters()) {
      manifest.filters = offscreen.renderer().filters().fingerprints();
      manifest.filterValues = offscreen.renderer().filters().snapshot();
    }
    claimFolder(folder, manifest, holdsFrames(folder));
    // What is there already, judged once: frames kept are not rendered again (--checkpoints-only keeps all).
    std::vector<Found> found(end - first, Found::Whole);
    if (!options.checkpointsOnly)
      for (uint32_t frame = first; frame < end; ++frame)
        found[frame - first] = existingFrame(framePath(folder, frame, options.format), config.size);
    const auto missing = std::find_if(found.begin(), found.end(), [](Found f) { return f != Found::Whole; });
    const uint32_t firstToWrite = first + uint32_t(missing - found.begin());

    const bool checkpointing = offscreen.renderer().scene().checkpoints();
    if (options.checkpointEvery > 0 && !checkpointing)
      std::fprintf(stderr, "vitrine: %s cannot be checkpointed (its picture carries history); no checkpoints written\n",
                   options.scene.c_str());
    const std::string film = fingerprint(manifestText(manifest));
    if (checkpointing) resumedAt = resumeFromCheckpoint(offscreen, inputs.sound, folder, manifest, firstToWrite, options.spp);
    const uint32_t start = resumedAt.value_or(0);

    RecordProgress progress(end - first);
    resident.emplace(end - start);
    for (uint32_t frame = start; frame < end; ++frame) {
      resident->before(frame - start);
      const std::filesystem::path path = framePath(folder, frame, options.format);
      const Found state = frame >= first ? found[frame - first] : Found::Whole;
      const bool wanted = state != Found::Whole;
      if (state == Found::Broken) {
        std::fprintf(stderr, "vitrine: %s is not a whole %ux%u frame; rendering it again\n", path.filename().c_str(),
                     config.size.width, config.size.height);
        ++redone;
      }
      // Simulated all the same when not wanted: a later frame depends on it.
      const ImageRgba frameImage = renderFrame(offscreen, options.spp, wanted);
      if (wanted) {
        writeImage(path, frameImage);  // throws, naming the system's reason, when the disk does not take it whole
        ++written;
      }
      const uint32_t next = frame + 1;
      if (checkpointing && options.checkpointEvery > 0 && next % options.checkpointEvery == 0 && next < frames &&
          !std::filesystem::exists(checkpointPath(folder, next), ec)) {
        writeCheckpoint(checkpointPath(folder, next), {film, options.scene, device.properties().deviceName, next,
                                                       inputs.sound.commands(), offscreen.saveSimulation()});
        ++saved;
      }
      if (frame >= first) progress.update(frame - first + 1, written);
    }
  }
  if (inputs.events) inputs.events->close();
  // The film's sound, whole, when this run covered the whole film and the scene made any.
  const bool whole = first == 0 && end == frames;
  if (whole) writeFilmSound(folder / "audio.wav", inputs.sound, inputs.live.get(), options.time, double(frames) / options.fps);
  if (const std::string line = resident->line(); !line.empty()) std::printf("%s\n", line.c_str());
  std::printf("recorded %u of frames %u..%u%s into %s (%ux%u, %s, %.6g fps, %u samples a frame, scene %s) on %s%s%s\n",
              written, first, end - 1, redone ? fmt::format(" ({} not whole before)", redone).c_str() : "", folder.c_str(), config.size.width, config.size.height, options.format.c_str(),
              options.fps, options.spp, options.scene.c_str(), device.properties().deviceName,
              resumedAt ? fmt::format(", simulated from the checkpoint at frame {}", *resumedAt).c_str() : "",
              saved ? fmt::format(", {} checkpoint{} written", saved, saved == 1 ? "" : "s").c_str() : "");
  if (instance.validationMessages() > 0) {
    std::fprintf(stderr, "%d validation messages: failing.\n", instance.validationMessages());
    return 3;
  }
  return 0;
}

}  // namespace vitrine::host
