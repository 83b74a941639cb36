#pragma once
// The pass "glass post" (post.comp): the accumulated history to the output, tone-mapped (the seed
// optics clip at 1; physical optics roll HDR highlights off with a filmic curve), then FXAA if chosen.
#include "scenes/glass/settings.h"
#include "scenes/scene.h"
#include "shaders/glass/pass_push.h"

#include <array>
#include <memory>

namespace vitrine::glass {

class PostPass {
 public:
  explicit PostPass(gpu::ProgramLibrary& programs) : programs_(programs) {}
  void record(const FrameContext& frame, gpu::Image& accumulated, const Settings& settings, VkExtent2D extent);

 private:
  // One program for each combination of FXAA and the filmic curve (pass_push.h: GLASS_POST_*), built
  // the first time it is used.
  gpu::ProgramLibrary& programs_;
  std::array<std::unique_ptr<gpu::ComputeProgram>, GLASS_POST_OPTION_COMBINATIONS> byOptions_;
};

}  // namespace vitrine::glass
