#include "scenes/glass/post_pass.h"

#include "scenes/glass/sample_pass.h"
#include "shaders/glass/pass_push.h"

namespace vitrine::glass {

void PostPass::record(const FrameContext& frame, gpu::Image& accumulated, const Settings& settings, VkExtent2D extent) {
  const uint32_t options = (settings.aa == Antialiasing::Fxaa ? GLASS_POST_FXAA : 0u) |
                           (settings.optics == Optics::Physical ? GLASS_POST_FILMIC : 0u);
  auto& program = byOptions_[options];
  if (!program)
    program = std::make_unique<gpu::ComputeProgram>(programs_, "glass/post.comp",
                                                    gpu::ProgramOptions{.specialization = {int32_t(options)}});
  sampleInto(frame, *program, {"accumulated", "target"}, accumulated, frame.target, frame.target.view(), extent);
}

}  // namespace vitrine::glass
