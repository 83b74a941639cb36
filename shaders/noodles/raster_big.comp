#version 460
// The segments raster.comp listed as too big for one invocation (near the camera): a workgroup of
// 8x8 invocations takes each, walks its box in tiles of 8x8 pixels (cells, at one sample a pixel),
// skips the tiles its capsule cannot reach (tileMayHit: a long, thin tube's box is mostly empty) and
// casts one pixel's samples an invocation in the rest. The groups (at most MAX_BIG_GROUPS, dispatched indirectly from the count) stride through
// the list.
#extension GL_GOOGLE_include_directive : require
#include "noodles/raster.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  uint listed = min(counters.listed, NOODLES_BIG_LIST_CAPACITY);
  ScreenView view = screenView();
  // With four samples a pixel an invocation takes a pixel, so a tile is 16 x 16 cells, started on a
  // pixel's first cell.
  uint side = TILE_SIDE * SAMPLES_PER_AXIS;
  for (uint entry = gl_WorkGroupID.x; entry < listed; entry += gl_NumWorkGroups.x) {
    Segment s = loadSegment(bigSegments[entry]);
    ivec4 cells = capsuleCells(view, capsuleEndBoxes(view, s.a, s.b, pc.tubeRadius), SAMPLES_PER_AXIS);
    uvec2 start = uvec2(cells.xy) & ~uvec2(SAMPLES_PER_AXIS - 1u);
    uvec2 tiles = (uvec2(cells.zw) - start) / side + 1u;
    for (uint t = 0u; t < tiles.x * tiles.y; ++t) {  // the same tiles, in step, for the whole group
      uvec2 first = start + uvec2(t % tiles.x, t / tiles.x) * side;
      if (!tileMayHit(view, s.a, s.b, pc.tubeRadius, first, side, SAMPLES_PER_AXIS)) continue;
      uvec2 cell = first + gl_LocalInvocationID.xy * SAMPLES_PER_AXIS;
      if (any(greaterThan(ivec2(cell), cells.zw))) continue;
      if (SAMPLES_PER_AXIS == 2u) rasterPixel(cell / 2u, cells, s);
      else rasterSample(cell, s);
    }
  }
}
