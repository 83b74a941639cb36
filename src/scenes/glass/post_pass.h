#pragma once
// The pass "glass post" (post.comp): the accumulated history to the output, tone-mapped (the seed
// optics clip at 1; physical optics roll HDR highlights off with a filmic curve), then FXAA if chosen.
#include "scenes/glass/settings.h"
#include "scenes/scene.h"

namespace vitrine::glass {

class PostPass {
 public:
  explicit PostPass(gpu::ProgramLibrary& programs);
  void record(const FrameContext& frame, gpu::Image& accumulated, const Settings& settings, VkExtent2D extent) const;

 private:
  gpu::ComputeProgram program_;
};

}  // namespace vitrine::glass
