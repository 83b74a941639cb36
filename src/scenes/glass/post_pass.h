#pragma once
// The pass "glass post" (post.comp): the accumulated history to the output, tone-mapped (the seed
// optics clip at 1; physical optics roll HDR highlights off with a filmic curve), then FXAA if chosen.
#include "gpu/program_variants.h"
#include "scenes/glass/settings.h"
#include "scenes/scene.h"

namespace vitrine::glass {

class PostPass {
 public:
  explicit PostPass(gpu::ProgramLibrary& programs) : byOptions_(programs, "glass/post.comp") {}
  void record(const FrameContext& frame, gpu::Image& accumulated, const Settings& settings, VkExtent2D extent) const;

 private:
  // post.comp specialised on its options, FXAA and the filmic curve (pass_push.h: GLASS_POST_*).
  gpu::ComputeVariants byOptions_;
};

}  // namespace vitrine::glass
