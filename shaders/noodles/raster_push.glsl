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

// Chunk-local segment `index` is segment index / chunkStrands of strand index % chunkStrands (the
// nodes' node-major order, packing.glsl).
uint chunkSegments() { return pc.chunkStrands * pc.segmentsPerStrand; }

// The chunk-local strand walked `position`-th (NoodlesRasterPush::walk): nearest the camera first.
// Mirrors src/scenes/noodles/strand_walk.h, which says why.
uint walkedStrand(uint position) {
  uvec3 dims = uvec3(pc.walkX, pc.walkY, pc.chunkStrands / (pc.walkX * pc.walkY));
  uint slow = pc.walk & NOODLES_WALK_AXIS_MASK;
  uint middle = (pc.walk >> NOODLES_WALK_MIDDLE_SHIFT) & NOODLES_WALK_AXIS_MASK;
  uint fast = 3u - slow - middle;
  uvec3 c;
  c[fast] = position % dims[fast];
  uint rest = position / dims[fast];
  c[middle] = rest % dims[middle];
  c[slow] = rest / dims[middle];
  bvec3 flipped = notEqual((uvec3(pc.walk) >> (NOODLES_WALK_FLIP_SHIFT + uvec3(0u, 1u, 2u))) & 1u, uvec3(0u));
  c = mix(c, dims - 1u - c, flipped);
  return c.x + dims.x * (c.y + dims.y * c.z);
}

// This phase's segments (NoodlesRasterPush::phase) and the chunk-local segment its invocation i takes.
// Invocations run strand-major: neighbours take consecutive segments of one strand, whose boxes touch
// on screen, so their key reads and atomics share cache lines (10^8 segments at 1080p on the H200:
// 17.4 ms node-major, 9.26 strand-major, both in index order). The phases pick from the walk: the
// occluders are every NOODLES_OCCLUDER_STRIDE-th strand walked, the rest the others.
uint phaseSegments() { return pc.phaseStrands * pc.segmentsPerStrand; }
uint phaseSegment(uint i) {
  uint j = i / pc.segmentsPerStrand;
  uint segment = i - j * pc.segmentsPerStrand;
  uint walked = pc.phase == NOODLES_RASTER_OCCLUDERS ? j * NOODLES_OCCLUDER_STRIDE
              : pc.phase == NOODLES_RASTER_REST      ? j + j / (NOODLES_OCCLUDER_STRIDE - 1u) + 1u
                                                     : j;
  return segment * pc.chunkStrands + walkedStrand(walked);
}
// The segment's name in the visibility buffer: unique across chunks.
uint segmentId(uint index) { return pc.firstStrand * pc.segmentsPerStrand + index; }

#endif
