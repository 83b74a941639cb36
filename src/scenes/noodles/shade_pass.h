#pragma once
// Shades every pixel of the target once from the raster pass's visibility buffer (shade.comp): each
// sample's segment is cast again for its hit, normal and place along the strand, lit as the tubes
// always were, and the samples averaged. One dispatch per chunk of strands, the first writing the
// background too, later ones adding their own segments' samples.
#include "gpu/program.h"
#include "gpu/resources.h"
#include "scenes/noodles/strand_layout.h"
#include "scenes/noodles/tube_view.h"
#include "scenes/scene.h"

#include <array>
#include <memory>

namespace vitrine::noodles {

class ShadePass {
 public:
  explicit ShadePass(gpu::ProgramLibrary& programs) : programs_(programs) {}
  void record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, gpu::Buffer& visibility,
              uint32_t samplesPerAxis, const TubeView& view) const;

 private:
  gpu::ProgramLibrary& programs_;
  // shade.comp for 1 or 2 samples along a pixel's side (raster_pass.h: withSamples), built when first used.
  mutable std::array<std::unique_ptr<gpu::ComputeProgram>, 2> bySamples_;
};

}  // namespace vitrine::noodles
