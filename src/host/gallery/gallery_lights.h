#pragma once
// The room's lights in the gallery (docs/LIGHTS.md): the lights thread (lights/lights.h) and the small
// readback that feeds it. Each frame, after the flash guard, the shown frame is drawn at
// lights::kRegionWidth x kRegionHeight (256x144, one bilinear tap a texel) into an image of its own and
// copied back without waiting (a ReadbackOutput, 144 KiB); the newest copy that has finished, with the
// scene's own signals, goes to the lights thread, which measures regions and dominant colours there.
#include "host/present/readback_output.h"
#include "lights/lights.h"

#include <functional>
#include <memory>
#include <string>

namespace vitrine::host {

class SceneRenderer;
struct Crossfade;

class GalleryLights {
 public:
  using SceneSignals = std::function<lights::Signals()>;
  // Throws vitrine::Error for a patch that is wrong (file:line).
  GalleryLights(const gpu::Device& device, const std::string& patchFile, SceneSignals sceneSignals);
  ~GalleryLights();

  lights::Lights& lights() { return *lights_; }
  // After the frame's other outputs: the reduced frame, when a buffer is free.
  void record(VkCommandBuffer cmd, uint32_t slot, SceneRenderer& renderer, const Crossfade& fade, VkPipelineStageFlags2 stage,
              const FrameInput& shown);
  void present() { output_->present(); }
  // The blackout key: on or off; returns the note the screen shows.
  std::string toggleBlackout();

 private:
  std::unique_ptr<lights::Lights> lights_;
  std::unique_ptr<ReadbackOutput> output_;
};

}  // namespace vitrine::host
