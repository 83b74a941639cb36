#include "scenes/glass/post_pass.h"

#include "scenes/glass/sample_pass.h"
#include "shaders/glass/pass_push.h"

namespace vitrine::glass {

void PostPass::record(const FrameContext& frame, gpu::Image& accumulated, const Settings& settings,
                      VkExtent2D extent) const {
  const uint32_t options = (settings.aa == Antialiasing::Fxaa ? GLASS_POST_FXAA : 0u) |
                           (settings.optics == Optics::Physical ? GLASS_POST_FILMIC : 0u);
  sampleInto(frame, byOptions_({int32_t(options)}), {"accumulated", "target"}, accumulated, frame.target,
             frame.target.view(), extent);
}

}  // namespace vitrine::glass
