// What raster.comp and raster_big.comp share: the buffers and casting one sample's ray at one
// segment, keeping the nearer of it and what the sample holds.
#ifndef NOODLES_RASTER_GLSL
#define NOODLES_RASTER_GLSL
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "noodles/packing.glsl"
#include "noodles/raster_blocks.h"
#include "noodles/raster_push.glsl"

const uint TILE_SIDE = 8u;  // a tile is 8 x 8 sample cells: one cell per invocation of a big-segment group
const uint MAX_BIG_GROUPS = 65535u;  // the big-segment pass's workgroups at most (the guaranteed limit)

layout(binding = 0, std430) readonly buffer Nodes { uvec4 nodes[]; };  // this chunk's nodes
// One 64-bit key per sample: ordered distance bits high, segment id low; all ones is empty. Samples
// of a pixel are adjacent, so the shade pass reads one pixel's in one go.
layout(binding = 1, std430) buffer Visibility { uint64_t keys[]; };
// Segments too big for one invocation (chunk-local indices), for raster_big.comp.
layout(binding = 2, std430) buffer BigSegments { uint bigSegments[]; };
// The big-segment pass's indirect dispatch, then how many segments were listed.
layout(binding = 3, std430) buffer Counters { NoodlesBigSegmentCounters counters; };
// Each tile's farthest held depth (orderedBits; all ones while any sample is empty), from
// tile_bound.comp between the occluders and the rest.
layout(binding = 4, std430) readonly buffer TileFar { uint tileFar[]; };

struct Segment {
  vec3 a, b;
  uint id;
  // The strand's nodes either side, when hits must be checked against the neighbouring capsules
  // (insideCapsule in capsule.h says why): only near the near plane.
  bool checkBefore, checkAfter;
  vec3 before, after;
  uint nearestBits;  // orderedBits of the nearest any hit can be: a sample already nearer needs no ray
};

Segment loadSegment(uint index) {
  uint segment = index / pc.chunkStrands;
  uint local = index - segment * pc.chunkStrands;
  Segment s;
  s.a = nodePosition(nodes[nodeSlot(pc.chunkStrands, pc.segmentsPerStrand + 1u, local, segment)]);
  s.b = nodePosition(nodes[nodeSlot(pc.chunkStrands, pc.segmentsPerStrand + 1u, local, segment + 1u)]);
  s.id = segmentId(index);
  // A neighbour's hit can be cut away only if it reaches in front of the near plane, which it can
  // only near this segment: within the radius twice and the neighbour's length, taken as at most
  // four times this one's (consecutive steps of a smooth flow differ far less).
  float reach = pc.nearPlane + 2.0 * pc.tubeRadius + 4.0 * length(s.b - s.a);
  bool near = min(dot(s.a - pc.eye, pc.forward), dot(s.b - pc.eye, pc.forward)) < reach;
  s.checkBefore = near && segment > 0u;
  s.checkAfter = near && segment + 1u < pc.segmentsPerStrand;
  s.before = s.checkBefore ? nodePosition(nodes[nodeSlot(pc.chunkStrands, pc.segmentsPerStrand + 1u, local, segment - 1u)]) : s.a;
  s.after = s.checkAfter ? nodePosition(nodes[nodeSlot(pc.chunkStrands, pc.segmentsPerStrand + 1u, local, segment + 2u)]) : s.b;
  s.nearestBits = orderedBits(nearestPossibleHit(pc.eye, s.a, s.b, pc.tubeRadius));
  return s;
}

// Whether every tile of the box (cells, in samples) holds only hits nearer than `nearestBits`, so the
// segment can put nothing there: then no ray and no key needs reading. Boxes over more than nine
// tiles (3x3) are left to the per-sample test (near the camera, where they are few; H200, 10^7
// segments at 3840x2160, stride 8: 14.63 ms raster with four tiles at most, 13.73 with nine, the same
// with sixteen).
bool hiddenByTiles(ivec4 cells, uint nearestBits) {
  uvec4 tiles = uvec4(cells) / (SAMPLES_PER_AXIS * NOODLES_BOUND_TILE);
  if ((tiles.z - tiles.x + 1u) * (tiles.w - tiles.y + 1u) > 9u) return false;
  for (uint y = tiles.y; y <= tiles.w; ++y)
    for (uint x = tiles.x; x <= tiles.z; ++x)
      if (tileFar[y * pc.tilesPerRow + x] >= nearestBits) return false;
  return true;
}

// The ray of sample cell `cell` (key `sample_`, whose depth bits read `held`) at the segment: its
// hit, if nearer than what the key holds, goes in with an atomicMin.
void castSample(uvec2 cell, uint sample_, uint held, Segment s) {
  vec3 direction = normalize(rayThrough(screenView(), cellSamplePosition(cell, SAMPLES_PER_AXIS)));
  float t = capsuleHit(pc.eye, direction, s.a, s.b, pc.tubeRadius);
  if (t == NO_HIT || t * dot(direction, pc.forward) < pc.nearPlane) return;
  vec3 hit = pc.eye + t * direction;
  if (s.checkBefore && insideCapsule(hit, s.before, s.a, pc.tubeRadius)) return;
  if (s.checkAfter && insideCapsule(hit, s.b, s.after, pc.tubeRadius)) return;
  uint depth = orderedBits(t);
  if (depth > held) return;
  atomicMin(keys[sample_], (uint64_t(depth) << 32) | uint64_t(s.id));
}

// Keys only fall, so a plain read already nearer than anything this segment can put there (stale,
// or even torn: its high half is still some key's depth) spares the ray, and one nearer than the
// ray's hit spares the atomic: at ~16 hits a sample (10^6 segments at 1080p) most are skipped so.
// (The read first is the faster order: docs/PERFORMANCE.md, noodles, Decisions.)
void rasterSample(uvec2 cell, Segment s) {
  uvec2 pixel = cell / SAMPLES_PER_AXIS;
  uvec2 quarter = cell - pixel * SAMPLES_PER_AXIS;
  uint sample_ = (pixel.y * uint(pc.pixels.x) + pixel.x) * SAMPLES_PER_AXIS * SAMPLES_PER_AXIS +
                 quarter.y * SAMPLES_PER_AXIS + quarter.x;
  uint held = uint(keys[sample_] >> 32);
  if (s.nearestBits <= held) castSample(cell, sample_, held, s);
}

// The four samples of a pixel (two samples an axis) at once: their keys are adjacent, one read
// between them, and a pixel whose four samples all hold nearer hits is passed over whole.
void rasterPixel(uvec2 pixel, ivec4 cells, Segment s) {
  uint first = (pixel.y * uint(pc.pixels.x) + pixel.x) * 4u;
  uvec4 held = uvec4(keys[first] >> 32, keys[first + 1u] >> 32, keys[first + 2u] >> 32, keys[first + 3u] >> 32);
  if (all(greaterThan(uvec4(s.nearestBits), held))) return;
  for (uint q = 0u; q < 4u; ++q) {
    uvec2 cell = pixel * 2u + uvec2(q & 1u, q >> 1u);
    if (s.nearestBits <= held[q] && all(greaterThanEqual(ivec2(cell), cells.xy)) && all(lessThanEqual(ivec2(cell), cells.zw)))
      castSample(cell, first + q, held[q], s);
  }
}

#endif
