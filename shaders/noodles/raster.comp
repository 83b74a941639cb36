#version 460
// One invocation per segment (dispatched per chunk of strands, per phase: raster_blocks.h): cull it, bound its capsule on
// screen, and cast the rays of the samples in that box itself when there are not many, row by row only
// where the hull of its end spheres reaches (a thin diagonal segment fills a sliver of its box); a bigger box
// (a segment near the camera) is listed for raster_big.comp, where a workgroup takes the segment, so
// no invocation loops over thousands of samples while its neighbours idle.
#extension GL_GOOGLE_include_directive : require
#include "noodles/raster.glsl"

layout(local_size_x = 64) in;

// Boxes of up to this many cells are cast inline. At 10^6 segments at 1080p (flight camera, t = 0) a
// segment's box averages ~240 cells; 256 keeps ~2/3 of the cells inline at ~45 % lane use (a warp
// waits for its biggest box). Measured on the H100 against 64, 128 and 512 (and against culling the
// inline boxes' 4x4 tiles with tileMayHit): the fastest at 10^6 and 10^7 segments in one pass. A
// nest drawn in two phases keeps boxes of up to 512 inline: its occluders are few and spread, and
// most of the rest's boxes are dropped on their tiles or their keys, so a listed box costs a
// workgroup for little, while 512 in one pass slows the default nest (docs/PERFORMANCE.md, noodles,
// Decisions).
const uint MOST_CELLS_INLINE = 256u;
const uint MOST_CELLS_INLINE_TWO_PHASES = 512u;

// Every sample cell of the box that the hull of the end boxes reaches, row by row.
void rasterBox(ivec4 cells, EndBoxes ends, Segment s) {
  float pixelsPerCell = 1.0 / float(SAMPLES_PER_AXIS);
  for (int y = cells.y; y <= cells.w; ++y) {
    ivec2 columns = hullColumns(ends, float(y) * pixelsPerCell, float(y + 1) * pixelsPerCell, cells, SAMPLES_PER_AXIS);
    for (int x = columns.x; x <= columns.y; ++x) rasterSample(uvec2(x, y), s);
  }
}

void main() {
  uint invocation = gl_GlobalInvocationID.y * pc.invocationsPerRow + gl_GlobalInvocationID.x;
  if (invocation >= phaseSegments()) return;
  uint index = phaseSegment(invocation);
  Segment s = loadSegment(index);
  EndBoxes ends = capsuleEndBoxes(screenView(), s.a, s.b, pc.tubeRadius);
  ivec4 cells = capsuleCells(screenView(), ends, SAMPLES_PER_AXIS);
  if (cells.x > cells.z || cells.y > cells.w) return;
  if (pc.phase == NOODLES_RASTER_REST && hiddenByTiles(cells, s.nearestBits)) return;
  uvec2 size = uvec2(cells.zw - cells.xy) + 1u;
  if (size.x * size.y <= (pc.phase == NOODLES_RASTER_ALL ? MOST_CELLS_INLINE : MOST_CELLS_INLINE_TWO_PHASES)) {
    if (SAMPLES_PER_AXIS == 2u) {
      for (int y = cells.y >> 1; y <= cells.w >> 1; ++y) {
        ivec2 columns = hullColumns(ends, float(y), float(y + 1), cells, 2u);
        for (int x = columns.x >> 1; x <= columns.y >> 1; ++x) rasterPixel(uvec2(x, y), cells, s);
      }
      return;
    }
    rasterBox(cells, ends, s);
    return;
  }
  uint slot = atomicAdd(counters.listed, 1u);
  if (slot < NOODLES_BIG_LIST_CAPACITY) {
    bigSegments[slot] = index;
    if (slot < MAX_BIG_GROUPS) atomicAdd(counters.groupsX, 1u);  // a workgroup each, up to the limit
    return;
  }
  rasterBox(cells, ends, s);  // the list is full (a pathological view): this invocation casts them itself
}
