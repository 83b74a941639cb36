#pragma once
// The pass "glass spectral": the per-wavelength work (shaders/glass/shade.glsl) for every pixel glass
// covers, writing the glass's light into the colour image (alpha 1 there) and each pixel's motion.
// Two paths give the same picture (the setting `pass`, Settings' SpectralPass):
// - compute (the default): one invocation a pixel tests the instances whose projected box holds it;
//   pixels without glass cost a few comparisons (spectral.comp).
// - raster, the original's: an instanced proxy per shape, its box turned with the shape or the
//   diamond's hull, back faces only, so every covered pixel runs the fragment shader once even with
//   the eye inside; depth from the surface hit sorts overlapping instances (proxy.vert, glass.frag).
// Each shape has its own programs (a specialization constant), built the first time it is shown.
#include "scenes/glass/diamond_buffers.h"
#include "scenes/glass/frame_sources.h"
#include "scenes/glass/screen_images.h"
#include "scenes/glass/settings.h"
#include "scenes/scene.h"

#include <array>
#include <memory>

namespace vitrine::glass {

class SpectralShadePass {
 public:
  explicit SpectralShadePass(gpu::ProgramLibrary& programs) : programs_(programs) {}
  void record(const FrameContext& frame, const FrameSources& sources, const ScreenImages& images,
              const DiamondBuffers& diamond, SpectralPass path, ShapeKind shape, VkExtent2D extent);

 private:
  const gpu::ComputeProgram& computeProgram(ShapeKind shape);
  const gpu::GraphicsProgram& rasterProgram(ShapeKind shape);

  gpu::ProgramLibrary& programs_;
  std::array<std::unique_ptr<gpu::ComputeProgram>, 5> compute_;  // by ShapeKind
  std::array<std::unique_ptr<gpu::GraphicsProgram>, 5> raster_;
};

}  // namespace vitrine::glass
