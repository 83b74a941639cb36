#pragma once
// The diamond on the GPU: its facet planes, which every spectral program reads (diamond.glsl), and its
// hull's triangles, the raster path's proxy. Made on the first frame and again when its size changes.
#include "gpu/resources.h"
#include "scenes/scene.h"

#include <optional>

namespace vitrine::glass {

class DiamondBuffers {
 public:
  void update(const FrameContext& frame, float size);

  gpu::Buffer& planes() { return *planes_; }
  gpu::Buffer& hull() { return *hull_; }
  uint32_t hullVertices() const { return hullVertices_; }

 private:
  std::optional<gpu::Buffer> planes_, hull_;
  uint32_t hullVertices_ = 0;
  float builtSize_ = 0.0f;
};

}  // namespace vitrine::glass
