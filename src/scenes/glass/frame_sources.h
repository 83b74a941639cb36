#pragma once
// What the spectral and the resolve programs both read (shaders/glass/frame.glsl, then the two
// samplers), bound by the names the shaders give them: this frame's block, the backdrop with its mips,
// clamped, and the panorama with its mips, wrapped around the sky.
#include "gpu/resources.h"
#include "scenes/scene.h"
#include "shaders/glass/frame_block.h"

namespace vitrine::glass {

struct FrameSources {
  gpu::StreamSlice block;  // a shader::GlassFrame
  gpu::Image& backdrop;
  gpu::Image& panorama;

  gpu::Bindings bindings(const gpu::Device& device) const {
    constexpr VkImageLayout kSampled = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    return gpu::Bindings()
        .storageBuffer("Frame", block.buffer, block.offset, sizeof(shader::GlassFrame))
        .sampledImage("backdrop", backdrop.view(),
                      device.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Clamp, true), kSampled)
        .sampledImage("panorama", panorama.view(),
                      device.sampler(gpu::Device::Filter::Linear, gpu::Device::Address::Repeat, true), kSampled);
  }
};

}  // namespace vitrine::glass
