#include "scenes/glass/post_pass.h"

#include "scenes/glass/sample_pass.h"
#include "shaders/glass/pass_push.h"

namespace vitrine::glass {

PostPass::PostPass(gpu::ProgramLibrary& programs) : program_(programs, "glass/post.comp") {}

void PostPass::record(const FrameContext& frame, gpu::Image& accumulated, const Settings& settings,
                      VkExtent2D extent) const {
  const shader::GlassPostPush push{.fxaa = settings.aa == Antialiasing::Fxaa ? 1u : 0u,
                                   .filmicCurve = settings.optics == Optics::Physical ? 1u : 0u};
  sampleInto(frame, program_, {"accumulated", "target"}, accumulated, frame.target, frame.target.view(), extent, push);
}

}  // namespace vitrine::glass
