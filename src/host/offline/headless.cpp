#include "core/resident_memory.h"
#include "gpu/check.h"
#include "gpu/memory_ledger.h"
#include "image/image_io.h"
#include "image/image_compare.h"
#include "audio/engine.h"
#include "audio/wav.h"
#include "host/user_presets.h"
#include "host/event_log.h"
#include "host/input_script.h"
#include "host/live_link.h"
#include "host/modes.h"
#include "host/filters/filter_options.h"
#include "host/offline/headless_stream.h"
#include "host/offline/offscreen.h"
#include "host/present/output_warp_file.h"
#include "host/scene_renderer.h"
#include "core/output_path.h"
#include "core/stop_signal.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>

#include "host/remote_link.h"
#include "lights/lights.h"
#include <fmt/format.h>

namespace vitrine::host {

int runHeadless(const Options& options) {
  const std::filesystem::path out = options.out;
  checkWritable(out);
  gpu::Instance instance({options.validation, {}});
  gpu::Device device(instance, {options.device});
  OffscreenConfig config{options.scene, options.size.value_or(VkExtent2D{320, 180}), options.time, options.seed,
                         options.reducedMotion, presetsFor(options, options.scene, true),
                         parametersFor(options, options.scene, true)};
  config.flashGuard = flashGuardOn(options);
  config.filters = filterSpecs(options);
  config.presetFiles = presetFilesFor(options, options.scene);
  if (!options.input.empty()) config.input = loadInputScript(options.input);
  if (!options.outputWarp.empty()) {
    config.warp = readOutputWarp(options.outputWarp);
    checkWarpedFrame(device, config.size, *config.warp, options.outputWarp);
  }
  std::optional<JsonLinesEventLog> events;
  if (!options.events.empty()) config.events = &events.emplace(options.events);
  const std::unique_ptr<LiveLink> live = offlineLiveInput(options, options.scene);
  config.live = live.get();
  // --lights: started before the first frame, so olad is found while the frames render.
  std::unique_ptr<lights::Lights> lightsOut;
  if (!options.lights.empty()) lightsOut = std::make_unique<lights::Lights>(lights::loadPatch(options.lights));
  if (lightsOut && live) live->setDmxInput(lightsOut.get());
  lights::Signals sceneLights;
  std::optional<audio::OfflineAudio> sound;  // outlives the offscreen run and its scene
  if (!options.audioOut.empty() || !options.stream.empty()) config.audio = &sound.emplace(options.time);
  ImageRgba image;
  uint32_t rendered = 0;  // fewer than --frames when SIGTERM ends a --remote run early
  std::optional<StopOnSignal> stop;  // a --remote or --stream run's, caught until the run has written its last frame
  {
    Offscreen offscreen(device, config);
    std::optional<RemoteLink> remote;
    std::optional<params::PresetStore> presets;  // a client may save, apply and delete presets
    std::optional<HeadlessStream> stream;
    if (!options.stream.empty()) {
      // Streamed live: frames are paced at 60 a second, and SIGTERM or Ctrl-C ends the run early.
      stream.emplace(device, options, offscreen.size(), config.warp, *sound, live.get(), options.frames);
      offscreen.addOutput(stream->output());
      stop.emplace();
    }
    if (options.remote) {
      // Driven by phones or a browser test: frames are paced at 60 a second, like a window's, and
      // SIGTERM ends the run early (the last frame is still written).
      remote.emplace(options.remoteBind, options.remoteAllow);
      remote->setPresets(&presets.emplace(openUserPresets()));
      if (live) remote->setMappings(live->mappingLines());
      if (!stop) stop.emplace();
    }
    auto due = std::chrono::steady_clock::now();
    // Device memory after the first fifth of the frames (the soak's warm-up) and at the end; resident
    // memory then and at twenty frames spread over the rest, for its peak: by frames, not seconds, so
    // that 10,000 frames that end within a second on a fast GPU are measured as well as slow ones.
    ResidentByFrames resident(options.frames);
    const uint32_t warmFrames = resident.warmFrames();
    gpu::MemoryTally warm;
    for (; rendered < options.frames && (rendered == 0 || !StopOnSignal::requested()); ++rendered) {  // one frame at least
      if (rendered == warmFrames) warm = gpu::liveDeviceMemory();
      resident.before(rendered);
      if (remote) {
        RemoteApplied applied = remote->apply(offscreen.renderer(), config.events, offscreen.time());
        if (live) for (const auto& [source, value] : applied.sources) live->sources().set(source, value);
        offscreen.addInput(std::move(applied.actions), remote->pointer(offscreen.size()));
        remote->publish(offscreen.renderer());
      }
      // Live input from outside (a phone, a stream's viewers, a lighting desk) plays at a window's pace.
      if (remote || stream || lightsOut) std::this_thread::sleep_until(due += std::chrono::microseconds(16667));
      offscreen.renderFrame();
    }
    if (stream) stream->finish(rendered);
    image = offscreen.readback();
    if (lightsOut) offscreen.renderer().scene().lightSignals(sceneLights);
    if (!options.savePreset.empty()) saveRunPreset(options, offscreen.parameters());  // the values it ended with
    const gpu::MemoryTally end = gpu::liveDeviceMemory();
    if (rendered > warmFrames)
      std::printf("device memory: %llu allocations, %.1f MiB after frame %u; %llu allocations, %.1f MiB at the end\n",
                  static_cast<unsigned long long>(warm.allocations), double(warm.bytes) / 1048576.0, warmFrames,
                  static_cast<unsigned long long>(end.allocations), double(end.bytes) / 1048576.0);
    if (const std::string line = resident.line(); !line.empty()) std::printf("%s\n", line.c_str());
    if (!offscreen.inputFinished())
      std::fprintf(stderr, "vitrine: %s has events after the last frame (t=%.3f s); they were not played\n",
                   options.input.c_str(), options.time + (double(rendered) - 1.0) / 60.0);
  }
  writeImage(out, image);
  if (lightsOut) {
    lightsOut->publish(lights::reduceImage(image), std::move(sceneLights));
    const bool sent = lightsOut->flush(3.0);
    std::printf("%s%s\n", lightsOut->status().c_str(), sent ? "" : " (the last frame's lights were not sent)");
  }
  if (events) events->close();
  if (sound && !options.audioOut.empty()) audio::writeWav(options.audioOut, sound->render(double(rendered) / 60.0));
  std::printf("wrote %s (%ux%u, scene %s, %u frames from t=%.3f s, seed %u) on %s\n", out.c_str(), image.width,
              image.height, options.scene.c_str(), rendered, options.time, options.seed,
              device.properties().deviceName);
  if (rendered < options.frames)
    std::printf("stopped after %u of the %u frames asked for\n", rendered, options.frames);
  if (instance.validationMessages() > 0) {
    std::fprintf(stderr, "%d validation messages: failing.\n", instance.validationMessages());
    return 3;
  }
  return 0;
}

int runCompare(const Options& options) {
  const ImageRgba reference = readImage(options.compare[0]);
  const ImageRgba candidate = readImage(options.compare[1]);
  const CompareResult result = compareImages(reference, candidate, options.compareThresholds);
  if (!result.sizeMatches) {  // readImage read both, so both are EXRs
    std::fprintf(stderr, "%s (reference %s and candidate %s, both EXR)\n", result.summary().c_str(),
                 options.compare[0].c_str(), options.compare[1].c_str());
    return 2;
  }
  std::fprintf(result.passed ? stdout : stderr, "%s\n", result.summary().c_str());  // a failure is a diagnostic
  return result.passed ? 0 : 2;
}

}  // namespace vitrine::host
