#pragma once
// The compute rasteriser of the tubes: clears the visibility buffer (one 64-bit key a sample: the
// nearest hit's ordered distance over its segment's id), then per chunk of strands one invocation
// per segment culls and bounds its capsule and casts the rays of a small box itself, listing a big
// segment for a second, indirect dispatch in which a workgroup takes each, tile by tile, skipping the
// tiles its tube cannot reach.
// The pass owns the visibility buffer (sized to the target and the sample count), the big-segment
// list and its counters; shade_pass.h reads the visibility buffer after it.
#include "gpu/program.h"
#include "gpu/resources.h"
#include "scenes/noodles/strand_layout.h"
#include "scenes/noodles/tube_view.h"
#include "scenes/scene.h"

namespace vitrine::noodles {

// Listed big segments (16 MiB): past it raster.comp casts a big box itself.
inline constexpr uint32_t kBigCapacity = 1u << 22;

class RasterPass {
 public:
  explicit RasterPass(const SceneContext& context);  // throws vitrine::Error without 64-bit buffer atomics
  void record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, const TubeView& view);

  gpu::Buffer& visibility() { return visibility_; }
  uint32_t samplesPerAxis() const { return samplesPerAxis_; }

 private:
  // (Re)allocates the visibility buffer for this size and sample count; the old one is retired.
  void ensureVisibility(VkExtent2D extent, bool multisample);

  const gpu::Device& device_;
  gpu::ComputeProgram segments_;
  gpu::ComputeProgram bigSegments_;
  gpu::Buffer visibility_;
  gpu::Buffer bigList_;
  gpu::Buffer counters_;  // VkDispatchIndirectCommand for the big-segment pass, then the listed count
  VkExtent2D extent_{0, 0};
  uint32_t samplesPerAxis_ = 0;
};

}  // namespace vitrine::noodles
