#pragma once
// The backdrop the glass refracts, made only when its source or the view's size changes (the pass
// "glass backdrop"): the photo covering the view, or the gradient or the checker (compose.comp); for
// the page, its paper and then its text; last, the full mip chain the spectral shaders' LOD rule reads.
#include "scenes/glass/backgrounds.h"
#include "scenes/glass/page_text.h"
#include "scenes/scene.h"

#include <glm/vec2.hpp>

namespace vitrine::glass {

class ComposePass {
 public:
  explicit ComposePass(const SceneContext& context);
  // `photoSize` in texels, 0 when there is no photo to show.
  void record(const FrameContext& frame, gpu::Image& backdrop, gpu::Image& photo, BackdropKind kind,
              glm::vec2 photoSize, VkExtent2D extent);

 private:
  gpu::ComputeProgram program_;
  PageText page_;
};

}  // namespace vitrine::glass
