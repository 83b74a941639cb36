#include "scenes/glass/post_pass.h"

#include "scenes/glass/sample_pass.h"

namespace vitrine::glass {
namespace {

struct PostPush {
  uint32_t fxaa;
  uint32_t filmic;
  uint32_t pad0, pad1;
};

}  // namespace

PostPass::PostPass(gpu::ProgramLibrary& programs)
    : program_(programs, "glass/post.comp",
               {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE}, sizeof(PostPush)}) {}

void PostPass::record(const FrameContext& frame, gpu::Image& accumulated, const Settings& settings,
                      VkExtent2D extent) const {
  const PostPush push{settings.aa == Antialiasing::Fxaa ? 1u : 0u, settings.optics == Optics::Physical ? 1u : 0u, 0, 0};
  sampleInto(frame, program_, accumulated, frame.target, frame.target.view(), extent, push);
}

}  // namespace vitrine::glass
