#pragma once
// The part of a frame that is the same in the gallery, headless and bench modes: keep the HDR target
// at the scene's render scale, let the scene record its passes, then blit the target into the
// caller's image (a swapchain image, or the offscreen output).
#include "gpu/barriers.h"
#include "gpu/resources.h"
#include "scenes/scene.h"

namespace vitrine::host {

struct BlitDestination {
  VkImage image;
  VkExtent2D extent;
  gpu::ImageUse before;  // how the image was last used
  gpu::ImageUse after;   // how the caller uses it next
};

class SceneRenderer {
 public:
  SceneRenderer(const gpu::Device& device, gpu::ProgramLibrary& programs, uint32_t framesInFlight);

  // Creates the scene; throws vitrine::Error if its set-up fails.
  void setScene(const SceneInfo& info);
  Scene& scene() { return *scene_; }
  const SceneInfo& info() const { return *info_; }
  gpu::PassTimer& timer() { return timer_; }

  void record(VkCommandBuffer cmd, uint32_t slot, const FrameInput& input, const BlitDestination& dst);
  const gpu::Image& target() const { return target_; }

 private:
  void ensureTarget(VkExtent2D output);
  const gpu::Device& device_;
  gpu::ProgramLibrary& programs_;
  uint32_t framesInFlight_;
  gpu::PassTimer timer_;
  const SceneInfo* info_ = nullptr;
  std::unique_ptr<Scene> scene_;
  gpu::Image target_;
};

}  // namespace vitrine::host
