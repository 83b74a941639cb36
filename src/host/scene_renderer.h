#pragma once
// The part of a frame that is the same in the gallery, headless and bench modes: keep the HDR target
// at the scene's render scale, let the scene record its passes, then scale the target onto the
// caller's image (a swapchain image, or the offscreen output) in a compute pass when the image
// allows storage writes, else with a blit. The target ends every frame in TRANSFER_SRC layout.
#include "gpu/barriers.h"
#include "gpu/resources.h"
#include "scenes/scene.h"

#include <string>
#include <utility>
#include <vector>

namespace vitrine::host {

struct BlitDestination {
  VkImage image;
  VkExtent2D extent;
  gpu::ImageUse before;                  // how the image was last used
  gpu::ImageUse after;                   // how the caller uses it next
  VkImageView storageView = VK_NULL_HANDLE;  // set when the image has STORAGE usage: compute path
  bool encodeSrgb = false;               // a UNORM image shown as sRGB (compute path only)
};

class SceneRenderer {
 public:
  SceneRenderer(const gpu::Device& device, gpu::ProgramLibrary& programs, uint32_t framesInFlight);

  // Creates the scene; throws vitrine::Error if its set-up fails.
  void setScene(const SceneInfo& info);
  Scene& scene() { return *scene_; }
  // "--set key=value" for the current scene; throws vitrine::Error naming a rejected one.
  void applyParameters(const std::vector<std::pair<std::string, std::string>>& parameters);
  const SceneInfo& info() const { return *info_; }
  gpu::PassTimer& timer() { return timer_; }

  void record(VkCommandBuffer cmd, uint32_t slot, const FrameInput& input, const BlitDestination& dst);
  const gpu::Image& target() const { return target_; }

 private:
  void ensureTarget(VkExtent2D output);
  void blit(VkCommandBuffer cmd, const BlitDestination& dst);
  void present(VkCommandBuffer cmd, const BlitDestination& dst);
  const gpu::Device& device_;
  gpu::ProgramLibrary& programs_;
  uint32_t framesInFlight_;
  gpu::PassTimer timer_;
  gpu::ComputeProgram present_;
  gpu::Unique<VkSampler> sampler_;
  const SceneInfo* info_ = nullptr;
  std::unique_ptr<Scene> scene_;
  gpu::Image target_;
};

}  // namespace vitrine::host
