#pragma once
// The pass "glass spectral": the per-wavelength work (shaders/glass/shade.glsl) for every pixel glass
// covers, writing the glass's light into the colour image (alpha 1 there) and each pixel's motion.
// Two paths give the same picture (the setting `pass`, Settings' SpectralPass):
// - compute (the default): one invocation a pixel tests the instances whose projected box holds it;
//   pixels without glass cost a few comparisons (spectral.comp).
// - raster, the original's: an instanced proxy per shape, its box turned with the shape or the
//   diamond's hull, back faces only, so every covered pixel runs the fragment shader once even with
//   the eye inside; depth from the surface hit sorts overlapping instances (proxy.vert, glass.frag).
// Each shape and combination of shading options has its own programs (specialization constants:
// instance.glsl's shape, shade.glsl's options), built the first time they are shown.
#include "scenes/glass/diamond_buffers.h"
#include "scenes/glass/frame_sources.h"
#include "scenes/glass/screen_images.h"
#include "scenes/glass/settings.h"
#include "scenes/scene.h"
#include "shaders/glass/frame_block.h"

#include <array>
#include <memory>

namespace vitrine::glass {

// What a spectral pipeline is specialised for.
struct ShadeVariant {
  ShapeKind shape;
  uint32_t options;  // frame_values.h: shadeOptions
  size_t index() const { return size_t(shape) * GLASS_SHADE_OPTION_COMBINATIONS + options; }
};

class SpectralShadePass {
 public:
  explicit SpectralShadePass(gpu::ProgramLibrary& programs) : programs_(programs) {}
  void record(const FrameContext& frame, const FrameSources& sources, const ScreenImages& images,
              const DiamondBuffers& diamond, SpectralPass path, ShadeVariant variant, VkExtent2D extent);

 private:
  const gpu::ComputeProgram& computeProgram(ShadeVariant variant);
  const gpu::GraphicsProgram& rasterProgram(ShadeVariant variant);

  static constexpr size_t kVariants = 5 * GLASS_SHADE_OPTION_COMBINATIONS;  // ShapeKind's five
  gpu::ProgramLibrary& programs_;
  std::array<std::unique_ptr<gpu::ComputeProgram>, kVariants> compute_;  // by ShadeVariant::index
  std::array<std::unique_ptr<gpu::GraphicsProgram>, kVariants> raster_;
};

}  // namespace vitrine::glass
