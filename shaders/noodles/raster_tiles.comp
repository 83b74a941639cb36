#version 460
// The big segments' tiles that raster.comp listed: a workgroup of 8x8 invocations takes a tile, one
// sample cell each, and the groups (at most MAX_TILE_GROUPS, dispatched indirectly from the count)
// stride through the list.
#extension GL_GOOGLE_include_directive : require
#include "noodles/raster.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  uint listed = min(tileCount, pc.tileCapacity);
  for (uint entry = gl_WorkGroupID.x; entry < listed; entry += gl_NumWorkGroups.x) {
    uvec2 item = tiles[entry];
    Segment s = loadSegment(item.x);
    // The box again, to leave out the cells of edge tiles outside it (cheaper than their rays).
    ivec4 cells = capsuleCells(screenView(), s.a, s.b, pc.radius, pc.samplesPerAxis);
    ivec2 cell = ivec2(uvec2(item.y & 0xffffu, item.y >> 16) * TILE_SIDE + gl_LocalInvocationID.xy);
    if (all(greaterThanEqual(cell, cells.xy)) && all(lessThanEqual(cell, cells.zw))) rasterSample(uvec2(cell), s);
  }
}
