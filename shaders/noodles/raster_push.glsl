// The push constants of the tube rasteriser's passes (raster.comp, raster_big.comp, shade.comp),
// declared with C++ in noodles/raster_blocks.h, and what the passes derive from them.
#ifndef NOODLES_RASTER_PUSH_GLSL
#define NOODLES_RASTER_PUSH_GLSL
#include "noodles/capsule.glsl"
#include "noodles/raster_blocks.h"

layout(push_constant) uniform Push { NoodlesRasterPush pc; };
// Samples along a pixel's side, 2 (four a pixel, one in each quarter) or 1 (one at the centre): a
// specialization constant, each pipeline built for one (raster_pass.h), so the cell arithmetic
// divides by a constant.
layout(constant_id = 0) const uint SAMPLES_PER_AXIS = 2u;

ScreenView screenView() {
  return ScreenView(pc.eye, pc.right, pc.up, pc.forward, pc.tanHalfX, pc.tanHalfY, pc.nearPlane, pc.pixels);
}

// Segments run node-major, like the nodes, so neighbouring invocations read neighbouring records:
// chunk-local segment `index` is segment index / chunkStrands of strand index % chunkStrands.
uint chunkSegments() { return pc.chunkStrands * pc.segmentsPerStrand; }
// This phase's segments (NoodlesRasterPush::phase) and the chunk-local segment its invocation i takes.
uint phaseSegments() { return pc.phaseStrands * pc.segmentsPerStrand; }
uint phaseSegment(uint i) {
  uint segment = i / pc.phaseStrands;
  uint j = i - segment * pc.phaseStrands;
  uint strand = pc.phase == NOODLES_RASTER_OCCLUDERS ? j * NOODLES_OCCLUDER_STRIDE
              : pc.phase == NOODLES_RASTER_REST      ? j + j / (NOODLES_OCCLUDER_STRIDE - 1u) + 1u
                                                     : j;
  return segment * pc.chunkStrands + strand;
}
// The segment's name in the visibility buffer: unique across chunks.
uint segmentId(uint index) { return pc.firstStrand * pc.segmentsPerStrand + index; }

#endif
