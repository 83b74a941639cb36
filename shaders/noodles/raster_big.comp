#version 460
// The segments raster.comp listed as too big for one invocation (near the camera): a workgroup of
// 8x8 invocations takes each, walks its cell box in 8x8 tiles, skips the tiles its capsule cannot
// reach (tileMayHit: a long, thin tube's box is mostly empty) and casts one cell an invocation in
// the rest. The groups (at most MAX_BIG_GROUPS, dispatched indirectly from the count) stride through
// the list.
#extension GL_GOOGLE_include_directive : require
#include "noodles/raster.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  uint listed = min(bigCount, pc.bigCapacity);
  ScreenView view = screenView();
  for (uint entry = gl_WorkGroupID.x; entry < listed; entry += gl_NumWorkGroups.x) {
    Segment s = loadSegment(bigSegments[entry]);
    ivec4 cells = capsuleCells(view, s.a, s.b, pc.radius, pc.samplesPerAxis);
    uvec2 tiles = uvec2(cells.zw - cells.xy) / TILE_SIDE + 1u;
    for (uint t = 0u; t < tiles.x * tiles.y; ++t) {  // the same tiles, in step, for the whole group
      uvec2 first = uvec2(cells.xy) + uvec2(t % tiles.x, t / tiles.x) * TILE_SIDE;
      if (!tileMayHit(view, s.a, s.b, pc.radius, first, TILE_SIDE, pc.samplesPerAxis)) continue;
      uvec2 cell = first + gl_LocalInvocationID.xy;
      if (all(lessThanEqual(cell, uvec2(cells.zw)))) rasterSample(cell, s);
    }
  }
}
