#pragma once
// The pass "glass resolve" (resolve.comp): every pixel once. Glass pixels take the spectral pass's
// colour, the others see the backdrop or the panorama directly; then the history, an exponential
// moving average read where the point was last frame (the spectral pass's motion) and clamped to the
// history's own running variance, so moving edges do not smear while the spectral noise averages out.
#include "scenes/glass/frame_sources.h"
#include "scenes/glass/screen_images.h"
#include "scenes/scene.h"

namespace vitrine::glass {

// How this frame joins the history.
struct Accumulation {
  bool restart = true;        // anything changed: the history starts again from this frame
  bool stopWorld = false;     // nothing moves: a progressive average, not reprojected
  float historyAlpha = 1.0f;  // the new frame's weight while the world moves
  uint32_t pausedFrames = 0;  // frames averaged since the world stopped or the average restarted
};

class ResolvePass {
 public:
  explicit ResolvePass(gpu::ProgramLibrary& programs);
  void record(const FrameContext& frame, const FrameSources& sources, const ScreenImages& images,
              const Accumulation& accumulation, VkExtent2D extent) const;

 private:
  gpu::ComputeProgram program_;
};

}  // namespace vitrine::glass
