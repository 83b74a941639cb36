#pragma once
// Shades every pixel of the target once from the raster pass's visibility buffer (shade.comp): each
// sample's segment is cast again for its hit, normal and place along the strand, lit as the tubes
// always were, and the samples averaged. One dispatch per chunk of strands, the first writing the
// background too, later ones adding their own segments' samples.
#include "gpu/program_variants.h"
#include "gpu/resources.h"
#include "scenes/noodles/strand_layout.h"
#include "scenes/noodles/tube_view.h"
#include "scenes/scene.h"

namespace vitrine::noodles {

class ShadePass {
 public:
  explicit ShadePass(gpu::ProgramLibrary& programs) : bySamples_(programs, "noodles/shade.comp") {}
  void record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, gpu::Buffer& visibility,
              uint32_t samplesPerAxis, const TubeView& view) const;

 private:
  // shade.comp specialised on the samples along a pixel's side, as the raster pass's programs are.
  gpu::ComputeVariants bySamples_;
};

}  // namespace vitrine::noodles
