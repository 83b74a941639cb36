#pragma once
// The compute step the compose and post passes share: one invocation a pixel of the view reads
// `source` through a linear, clamped sampler and writes `target` through `targetView`, with `push`
// as its constants (if it has any). Each shader names its two images as it likes (compose: photo and backdrop; post:
// accumulated and target): the pass says which name is which.
#include "gpu/resources.h"
#include "scenes/scene.h"

#include <string_view>
#include <type_traits>

namespace vitrine::glass {

struct SampleNames {
  std::string_view source;  // the shader's sampler2D
  std::string_view target;  // its storage image
};

struct NoConstants {};  // for a shader without a push block

template <typename Push = NoConstants>
void sampleInto(const FrameContext& frame, const gpu::ComputeProgram& program, SampleNames names, gpu::Image& source,
                gpu::Image& target, VkImageView targetView, VkExtent2D extent, const Push& push = {}) {
  frame.transition(source, gpu::use::ComputeSample);
  frame.transition(target, gpu::use::ComputeWrite);
  program.bind(frame.cmd);
  if constexpr (!std::is_same_v<Push, NoConstants>) program.constants(frame.cmd, push);
  program.push(frame.cmd,
               gpu::Bindings()
                   .sampledImage(names.source, source.view(),
                                 frame.device.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp),
                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
                   .storageImage(names.target, targetView));
  program.dispatchOver(frame.cmd, extent);
}

}  // namespace vitrine::glass
