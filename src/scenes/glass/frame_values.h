#pragma once
// The frame block's values (shaders/glass/frame_block.h), worked out on the CPU once a frame: the
// camera, the glass and its dispersion, the shape, its rotation now and last frame (for the motion
// vectors), and each instance's place with the pixels its turned box covers, which the compute path tests.
#include "scenes/glass/instances.h"
#include "scenes/glass/settings.h"
#include "shaders/glass/frame_block.h"

#include <vulkan/vulkan.h>

#include <cstdint>

namespace vitrine::glass {

// Where the scene stands this frame, besides its settings and its instances.
struct FrameMoment {
  VkExtent2D extent{1, 1};  // the view's pixels
  double time = 0.0, previousTime = 0.0;  // the scene's clock now and last frame; it stops with the world
  uint64_t frame = 0;
  uint32_t seed = 0;
  bool zHeld = false;  // three wavelengths without jitter
  Tier tier = Tier::High;  // the quality tier in use: its share of the wavelengths (tierWavelengths)
};

shader::GlassFrame frameBlock(const Settings& settings, const FrameMoment& moment, const Instances& instances);
// The block's options as shade.glsl's specialization constant (frame_block.h: GLASS_SHADE_*).
uint32_t shadeOptions(const shader::GlassFrame& block);

}  // namespace vitrine::glass
