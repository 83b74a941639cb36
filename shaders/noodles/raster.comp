#version 460
// One invocation per segment (dispatched per chunk of strands): cull it, bound its capsule on
// screen, and cast the rays of the samples in that box itself when there are not many; a bigger box
// (a segment near the camera) is listed as 8x8-cell tiles for raster_tiles.comp, where a workgroup
// takes each tile, so no invocation loops over thousands of samples while its neighbours idle.
#extension GL_GOOGLE_include_directive : require
#include "noodles/raster.glsl"

layout(local_size_x = 64) in;

// Boxes of up to this many cells are cast inline. At 10^6 segments at 1080p (flight camera, t = 0) a
// segment's box averages ~240 cells; 256 keeps ~2/3 of the cells inline at ~45 % lane use (a warp
// waits for its biggest box) and lists ~3.7 M tiles; 64 would list 7.7 M, past the list's capacity.
const uint MOST_CELLS_INLINE = 256u;

void main() {
  uint index = gl_GlobalInvocationID.y * pc.invocationsPerRow + gl_GlobalInvocationID.x;
  if (index >= chunkSegments()) return;
  Segment s = loadSegment(index);
  ivec4 cells = capsuleCells(screenView(), s.a, s.b, pc.radius, pc.samplesPerAxis);
  if (cells.x > cells.z || cells.y > cells.w) return;
  uvec2 size = uvec2(cells.zw - cells.xy) + 1u;
  if (size.x * size.y <= MOST_CELLS_INLINE) {
    for (int y = cells.y; y <= cells.w; ++y)
      for (int x = cells.x; x <= cells.z; ++x) rasterSample(uvec2(x, y), s);
    return;
  }
  uvec2 firstTile = uvec2(cells.xy) / TILE_SIDE, lastTile = uvec2(cells.zw) / TILE_SIDE;
  uvec2 tileSpan = lastTile - firstTile + 1u;
  uint count = tileSpan.x * tileSpan.y;
  uint base = atomicAdd(tileCount, count);
  // The tile pass runs min(listed, MAX_TILE_GROUPS) groups, each looping over the list: every
  // invocation that lists tiles below that bound adds its share.
  if (base < MAX_TILE_GROUPS) atomicAdd(tileGroups, min(base + count, MAX_TILE_GROUPS) - base);
  for (uint i = 0u; i < count; ++i) {
    uvec2 tile = firstTile + uvec2(i % tileSpan.x, i / tileSpan.x);
    if (base + i < pc.tileCapacity) {
      tiles[base + i] = uvec2(index, tile.x | (tile.y << 16));
      continue;
    }
    // The list is full (a pathological view): this invocation casts the tile's rays itself.
    uvec2 lo = max(tile * TILE_SIDE, uvec2(cells.xy)), hi = min(tile * TILE_SIDE + TILE_SIDE - 1u, uvec2(cells.zw));
    for (uint y = lo.y; y <= hi.y; ++y)
      for (uint x = lo.x; x <= hi.x; ++x) rasterSample(uvec2(x, y), s);
  }
}
