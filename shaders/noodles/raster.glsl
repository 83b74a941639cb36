// What raster.comp and raster_tiles.comp share: the buffers and casting one sample's ray at one
// segment, keeping the nearer of it and what the sample holds.
#ifndef NOODLES_RASTER_GLSL
#define NOODLES_RASTER_GLSL
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "noodles/packing.glsl"
#include "noodles/raster_push.glsl"

const uint TILE_SIDE = 8u;  // a tile is 8 x 8 sample cells: one cell per invocation of a tile group
const uint MAX_TILE_GROUPS = 65535u;  // the tile pass's workgroups at most (the guaranteed limit)

layout(binding = 0, std430) readonly buffer Nodes { uvec4 nodes[]; };  // this chunk's nodes
// One 64-bit key per sample: ordered distance bits high, segment id low; all ones is empty. Samples
// of a pixel are adjacent, so the shade pass reads one pixel's in one go.
layout(binding = 1, std430) buffer Visibility { uint64_t keys[]; };
// Tiles of segments too big for one invocation: (chunk-local segment, tile x | tile y << 16).
layout(binding = 2, std430) buffer Tiles { uvec2 tiles[]; };
// The tile pass's indirect dispatch (groups x, y, z), then how many tiles were listed.
layout(binding = 3, std430) buffer Counters { uint tileGroups; uint groupsY; uint groupsZ; uint tileCount; };

struct Segment {
  vec3 a, b;
  uint id;
  // The strand's nodes either side, when hits must be checked against the neighbouring capsules
  // (insideCapsule in capsule.h says why): only near the near plane.
  bool checkBefore, checkAfter;
  vec3 before, after;
};

Segment loadSegment(uint index) {
  uint segment = index / pc.chunkStrands;
  uint local = index - segment * pc.chunkStrands;
  Segment s;
  s.a = nodePosition(nodes[nodeSlot(pc.chunkStrands, local, segment)]);
  s.b = nodePosition(nodes[nodeSlot(pc.chunkStrands, local, segment + 1u)]);
  s.id = segmentId(index);
  // A neighbour's hit can be cut away only if it reaches in front of the near plane, which it can
  // only near this segment: within the radius twice and the neighbour's length, taken as at most
  // four times this one's (consecutive steps of a smooth flow differ far less).
  float reach = pc.nearPlane + 2.0 * pc.radius + 4.0 * length(s.b - s.a);
  bool near = min(dot(s.a - pc.eye, pc.forward), dot(s.b - pc.eye, pc.forward)) < reach;
  s.checkBefore = near && segment > 0u;
  s.checkAfter = near && segment + 1u < pc.segments;
  s.before = s.checkBefore ? nodePosition(nodes[nodeSlot(pc.chunkStrands, local, segment - 1u)]) : s.a;
  s.after = s.checkAfter ? nodePosition(nodes[nodeSlot(pc.chunkStrands, local, segment + 2u)]) : s.b;
  return s;
}

void rasterSample(uvec2 cell, Segment s) {
  vec3 direction = normalize(rayThrough(screenView(), cellSamplePosition(cell, pc.samplesPerAxis)));
  float t = capsuleHit(pc.eye, direction, s.a, s.b, pc.radius);
  if (t == NO_HIT || t * dot(direction, pc.forward) < pc.nearPlane) return;
  vec3 hit = pc.eye + t * direction;
  if (s.checkBefore && insideCapsule(hit, s.before, s.a, pc.radius)) return;
  if (s.checkAfter && insideCapsule(hit, s.b, s.after, pc.radius)) return;
  uvec2 pixel = cell / pc.samplesPerAxis;
  uvec2 quarter = cell - pixel * pc.samplesPerAxis;
  uint sample_ = (pixel.y * uint(pc.pixels.x) + pixel.x) * pc.samplesPerAxis * pc.samplesPerAxis +
                 quarter.y * pc.samplesPerAxis + quarter.x;
  uint depth = orderedBits(t);
  // Keys only fall, so a plain read whose depth is already nearer (stale, or even torn: its high
  // half is still some key's depth) makes the atomic pointless: at ~16 hits a sample (10^6 segments
  // at 1080p) most are skipped this way.
  if (depth > uint(keys[sample_] >> 32)) return;
  atomicMin(keys[sample_], (uint64_t(depth) << 32) | uint64_t(s.id));
}

#endif
