#pragma once
// The compute rasteriser of the tubes: clears the visibility buffer (one 64-bit key a sample: the
// nearest hit's ordered distance over its segment's id), then per chunk of strands one invocation
// per segment culls and bounds its capsule and casts the rays of a small box itself, listing a big
// segment for a second, indirect dispatch in which a workgroup takes each, tile by tile, skipping the
// tiles its tube cannot reach.
// The pass declares the visibility buffer (per pixel of the target, a key for each sample), the
// big-segment list and its counters; shade_pass.h reads the visibility buffer after it.
#include "gpu/frame_resources.h"
#include "gpu/program_variants.h"
#include "scenes/noodles/strand_layout.h"
#include "scenes/noodles/tube_view.h"
#include "scenes/scene.h"
#include "shaders/noodles/raster_blocks.h"

namespace vitrine::noodles {

// Nests of this many segments and more are drawn in two phases (raster_blocks.h): occluders, a bound
// a tile, the rest. Below it the occluders cover too little of the screen for the bound to pay.
inline constexpr uint64_t kTwoPhasesFrom = uint64_t(1) << 22;

class RasterPass {
 public:
  explicit RasterPass(const SceneContext& context);  // throws vitrine::Error without 64-bit buffer atomics
  void record(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes, const TubeView& view);

  gpu::Buffer& visibility(const FrameContext& frame) const { return frame.buffer(visibility_); }
  uint32_t samplesPerAxis() const { return samplesPerAxis_; }
  uint32_t workgroupSize() const { return kWorkgroupSize; }  // segments a workgroup takes

 private:
  // Redeclares the visibility buffer when the sample count changes (msaa, or a target too large for
  // four keys a pixel in one binding); the host resizes it with the target.
  void followSamples(const FrameContext& frame, bool multisample);
  // One phase of raster.comp over every chunk, each followed by its big segments.
  void recordPhase(const FrameContext& frame, const StrandLayout& layout, VkBuffer nodes,
                   shader::NoodlesRasterPush push, uint32_t phase);
  void recordTileBound(const FrameContext& frame, uint32_t tilesPerRow);

  // raster.comp's local size (checked against the shader's each time its program is taken).
  static constexpr uint32_t kWorkgroupSize = 64;
  // raster.comp and raster_big.comp, specialised on the samples along a pixel's side
  // (raster_push.glsl's SAMPLES_PER_AXIS, constant_id 0), as shade.comp is.
  gpu::ComputeVariants segments_, bigSegments_;
  gpu::ComputeProgram tileBound_;
  gpu::BufferHandle visibility_;
  gpu::BufferHandle bigList_;
  gpu::BufferHandle counters_;  // shader::NoodlesBigSegmentCounters
  gpu::BufferHandle tileFar_;   // a uint a tile of NOODLES_BOUND_TILE^2 pixels (declared a uint a pixel)
  uint32_t samplesPerAxis_;     // what the visibility buffer is declared for
  DeviceBudget budget_;         // the dispatch limits a phase's rows of workgroups keep to
};

}  // namespace vitrine::noodles
