#pragma once
// The compute step the compose and post passes share: one invocation a pixel of the view reads
// `source` through a linear, clamped sampler and writes `target` through `targetView`, with `push`
// as its constants (the program's bindings: the sampler, then the storage image).
#include "gpu/resources.h"
#include "scenes/scene.h"

namespace vitrine::glass {

template <typename Push>
void sampleInto(const FrameContext& frame, const gpu::ComputeProgram& program, gpu::Image& source, gpu::Image& target,
                VkImageView targetView, VkExtent2D extent, const Push& push) {
  frame.transition(source, gpu::use::ComputeSample);
  frame.transition(target, gpu::use::ComputeWrite);
  program.bind(frame.cmd);
  program.constants(frame.cmd, push);
  program.push(frame.cmd, gpu::Bindings()
                              .sampledImage(source.view(), frame.device.sampler(gpu::Device::Filter::Linear,
                                                                                gpu::Device::Address::Clamp),
                                            VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                              .storageImage(targetView));
  program.dispatchOver(frame.cmd, extent, {8, 8});
}

}  // namespace vitrine::glass
