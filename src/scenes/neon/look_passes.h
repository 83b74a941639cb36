#pragma once
// The neon scene's look after the geometry: the tubes' glow bloomed through a mip chain, depth of
// field from the depth buffer, and the composite (tint, vignette, grain, aberration, the ground's
// mirror, the tone map). All compute; the `stage` setting stops the picture after any of them.
#include "scenes/neon/settings.h"
#include "scenes/scene.h"

namespace vitrine::neon {

struct LookInputs {
  gpu::Image& scene;  // the facade and the tubes, HDR
  gpu::Image& depth;  // r32f, reverse-Z (near / distance), 0 for the sky
  gpu::Image& glow;   // the tubes alone, HDR: what blooms
  float mirrorRow;    // pixels from the top: the ground mirrors about this row
  float near;         // the projection's near distance
  float time;
  uint32_t dofTaps;   // the depth of field's spiral taps: fewer at the low tier
};

class LookPasses {
 public:
  explicit LookPasses(const SceneContext& context);
  void record(const FrameContext& frame, const Settings& settings, const LookInputs& in);

 private:
  // Returns the image whose first mip holds level 1, the bloom the composite adds.
  gpu::Image& bloom(const FrameContext& frame, const Settings& settings, gpu::Image& glow);

  const gpu::Device& device_;
  gpu::FrameResources& resources_;
  gpu::ComputeProgram down_, up_, dof_, composite_;
  gpu::ImageHandle downChain_, upChain_, focused_;
};

}  // namespace vitrine::neon
