#pragma once
// The diamond on the GPU (shaders/glass/diamond_blocks.h): its facet planes, which every spectral
// program reads (diamond.glsl), and its hull's triangles, the raster path's proxy. Declared with the
// scene's resources and redeclared when the stone's size changes, so the host uploads them as the
// next frame begins and retires the old ones.
#include "gpu/frame_resources.h"

#include <cstdint>

namespace vitrine::glass {

class DiamondBuffers {
 public:
  DiamondBuffers(gpu::FrameResources& resources, float size);
  // A stone of girdle diameter `size`: both buffers again when it differs from the last (from the
  // scene's update(), not while recording).
  void resize(float size);

  gpu::BufferHandle planes() const { return planes_; }  // a shader::GlassDiamond
  gpu::BufferHandle hull() const { return hull_; }      // shader::GlassHullVertex, hullVertices() of them
  uint32_t hullVertices() const { return hullVertices_; }

 private:
  gpu::FrameResources& resources_;
  gpu::BufferHandle planes_, hull_;
  uint32_t hullVertices_ = 0;
  float size_ = 0.0f;
};

}  // namespace vitrine::glass
