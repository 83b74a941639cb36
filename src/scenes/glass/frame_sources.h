#pragma once
// What the spectral and the resolve programs both read, bound first and in this order in both
// (shaders/glass/frame.glsl, then the two samplers): this frame's block, the backdrop with its mips,
// clamped, and the panorama with its mips, wrapped around the sky.
#include "gpu/resources.h"
#include "scenes/glass/frame_block.h"
#include "scenes/scene.h"

namespace vitrine::glass {

struct FrameSources {
  gpu::StreamSlice block;  // a FrameBlock
  gpu::Image& backdrop;
  gpu::Image& panorama;

  gpu::Bindings bindings(const gpu::Device& device) const {
    constexpr VkImageLayout kSampled = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    return gpu::Bindings()
        .storageBuffer(block.buffer, block.offset, sizeof(FrameBlock))
        .sampledImage(backdrop.view(), device.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp, true),
                      kSampled)
        .sampledImage(panorama.view(), device.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Repeat, true),
                      kSampled);
  }
};

}  // namespace vitrine::glass
