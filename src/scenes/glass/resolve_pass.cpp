#include "scenes/glass/resolve_pass.h"

#include "shaders/glass/pass_push.h"

#include <algorithm>

namespace vitrine::glass {

ResolvePass::ResolvePass(gpu::ProgramLibrary& programs) : program_(programs, "glass/resolve.comp") {}

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
  const shader::GlassResolvePush push{
      .alpha = alpha, .historyValid = valid ? 1u : 0u, .reproject = accumulation.stopWorld ? 0u : 1u};
  program_.bind(frame.cmd);
  program_.constants(frame.cmd, push);
  program_.push(frame.cmd,
                sources.bindings(frame.device)
                    .storageImage("colour", colour.view())
                    .storageImage("motion", motion.view())
                    .sampledImage("previous", previous.view(),
                                  frame.device.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp),
                                  VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                    .storageImage("history", current.view()));
  program_.dispatchOver(frame.cmd, extent);
}

}  // namespace vitrine::glass
