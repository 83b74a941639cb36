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
#include "gpu/program_variants.h"
#include "scenes/glass/diamond_buffers.h"
#include "scenes/glass/frame_sources.h"
#include "scenes/glass/screen_images.h"
#include "scenes/glass/settings.h"
#include "scenes/scene.h"
#include "shaders/glass/frame_block.h"


namespace vitrine::glass {

// What a spectral pipeline is specialised for.
struct ShadeVariant {
  ShapeKind shape;
  uint32_t options;  // frame_values.h: shadeOptions
};

class SpectralShadePass {
 public:
  explicit SpectralShadePass(gpu::ProgramLibrary& programs);
  void record(const FrameContext& frame, const FrameSources& sources, const ScreenImages& images,
              const DiamondBuffers& diamond, SpectralPass path, ShadeVariant variant, VkExtent2D extent) const;

 private:
  // Both paths' shaders specialised on the variant (instance.glsl's GLASS_SHAPE, shade.glsl's
  // GLASS_SHADE_OPTIONS), so that a cube's pipeline carries no diamond code, nor seed optics physical ones.
  gpu::ComputeVariants compute_;
  gpu::GraphicsVariants raster_;
};

}  // namespace vitrine::glass
