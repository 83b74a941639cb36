#include "scenes/glass/resolve_pass.h"

#include <algorithm>

namespace vitrine::glass {
namespace {

struct ResolvePush {
  float alpha;     // weight of this frame
  uint32_t valid;  // the history holds last frame
  uint32_t reproject;
  uint32_t pad;
};

}  // namespace

ResolvePass::ResolvePass(gpu::ProgramLibrary& programs)
    : program_(programs, "glass/resolve.comp",
               {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                 VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                 VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER,
                 VK_DESCRIPTOR_TYPE_STORAGE_IMAGE},
                sizeof(ResolvePush)}) {}

void ResolvePass::record(const FrameContext& frame, const FrameSources& sources, const ScreenImages& images,
                         const Accumulation& accumulation, VkExtent2D extent) const {
  gpu::Image& colour = frame.image(images.colour);
  gpu::Image& motion = frame.image(images.motion);
  gpu::Image& current = frame.image(images.history);
  gpu::Image& previous = frame.resources.previous(images.history);
  frame.transition(colour, gpu::use::ComputeRead);
  frame.transition(motion, gpu::use::ComputeRead);
  frame.transition(previous, gpu::use::HistoryRead);
  frame.transition(current, gpu::use::ComputeWrite);
  frame.transition(sources.backdrop, gpu::use::ComputeSample);
  frame.transition(sources.panorama, gpu::use::ComputeSample);
  const bool valid = frame.resources.historyValid(images.history) && !accumulation.restart;
  // Stop the world: a progressive average whose 1/256 floor keeps fp16 from rounding new samples away.
  const float alpha = !valid                  ? 1.0f
                      : accumulation.stopWorld ? std::max(1.0f / float(std::max(accumulation.pausedFrames, 1u)),
                                                          1.0f / 256.0f)
                                               : accumulation.historyAlpha;
  const ResolvePush push{alpha, valid ? 1u : 0u, accumulation.stopWorld ? 0u : 1u, 0u};
  program_.bind(frame.cmd);
  program_.constants(frame.cmd, push);
  program_.push(frame.cmd, sources.bindings(frame.device)
                               .storageImage(colour.view())
                               .storageImage(motion.view())
                               .sampledImage(previous.view(), frame.device.sampler(gpu::Device::Filter::Linear,
                                                                                   gpu::Device::Address::Clamp),
                                             VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                               .storageImage(current.view()));
  program_.dispatchOver(frame.cmd, extent, {8, 8});
}

}  // namespace vitrine::glass
