#version 460
// One invocation per segment (dispatched per chunk of strands, per phase: raster_blocks.h): cull it, bound its capsule on
// screen, and cast the rays of the samples in that box itself when there are not many; a bigger box
// (a segment near the camera) is listed for raster_big.comp, where a workgroup takes the segment, so
// no invocation loops over thousands of samples while its neighbours idle.
#extension GL_GOOGLE_include_directive : require
#include "noodles/raster.glsl"

layout(local_size_x = 64) in;

// Boxes of up to this many cells are cast inline. At 10^6 segments at 1080p (flight camera, t = 0) a
// segment's box averages ~240 cells; 256 keeps ~2/3 of the cells inline at ~45 % lane use (a warp
// waits for its biggest box). Measured on the H100 against 64, 128 and 512 (and against culling the
// inline boxes' 4x4 tiles with tileMayHit): the fastest at 10^6 and 10^7 segments.
const uint MOST_CELLS_INLINE = 256u;

void main() {
  uint invocation = gl_GlobalInvocationID.y * pc.invocationsPerRow + gl_GlobalInvocationID.x;
  if (invocation >= phaseSegments()) return;
  uint index = phaseSegment(invocation);
  Segment s = loadSegment(index);
  ivec4 cells = capsuleCells(screenView(), s.a, s.b, pc.tubeRadius, SAMPLES_PER_AXIS);
  if (cells.x > cells.z || cells.y > cells.w) return;
  if (pc.phase == NOODLES_RASTER_REST && hiddenByTiles(cells, s.nearestBits)) return;
  uvec2 size = uvec2(cells.zw - cells.xy) + 1u;
  if (size.x * size.y <= MOST_CELLS_INLINE) {
    if (SAMPLES_PER_AXIS == 2u) {
      for (int y = cells.y >> 1; y <= cells.w >> 1; ++y)
        for (int x = cells.x >> 1; x <= cells.z >> 1; ++x) rasterPixel(uvec2(x, y), cells, s);
      return;
    }
    for (int y = cells.y; y <= cells.w; ++y)
      for (int x = cells.x; x <= cells.z; ++x) rasterSample(uvec2(x, y), s);
    return;
  }
  uint slot = atomicAdd(counters.listed, 1u);
  if (slot < pc.bigListCapacity) {
    bigSegments[slot] = index;
    if (slot < MAX_BIG_GROUPS) atomicAdd(counters.groupsX, 1u);  // a workgroup each, up to the limit
    return;
  }
  // The list is full (a pathological view): this invocation casts the box's rays itself.
  for (int y = cells.y; y <= cells.w; ++y)
    for (int x = cells.x; x <= cells.z; ++x) rasterSample(uvec2(x, y), s);
}
