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
    // Cells of an edge tile outside the segment's box only miss: cheaper than bounding it again.
    uvec2 cell = uvec2(item.y & 0xffffu, item.y >> 16) * TILE_SIDE + gl_LocalInvocationID.xy;
    if (all(lessThan(cell, uvec2(pc.pixels) * pc.samplesPerAxis))) rasterSample(cell, s);
  }
}
