#pragma once
// The order the tube rasteriser takes a chunk's strands in: nearest the camera first. A sample keeps
// the nearest hit so far and a segment behind it is dropped on reading its key, before any ray is cast
// (raster.glsl), so the sooner the near strands land, the fewer casts and atomics the far ones cost
// (docs/PERFORMANCE.md, noodles, Decisions).
// The strands are seeded on a grid, x fastest, and stay near their seeds, so walking the grid with its
// most view-aligned axis slowest, every axis from the end nearer the eye, runs roughly front to back:
// the strands in flight at once are a slab facing the camera. Mirrored by raster_push.glsl's
// walkedStrand; tests/unit/noodles_walk_test.cpp checks both halves.
#include "shaders/noodles/raster_blocks.h"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace vitrine::noodles {

// How a chunk's strands are walked: the chunk as a grid, x fastest (a chunk that is not the whole
// grid is walked as a row), and NOODLES_WALK_* bits naming the slow and middle axes and the flips.
struct StrandWalk {
  glm::uvec3 dims{1};
  uint32_t code = 0;
};

// Walk bits for axes slowest to fastest (the fastest is the third) and the axes walked from their far
// end (bit 0 x, 1 y, 2 z).
constexpr uint32_t walkCode(uint32_t slow, uint32_t middle, uint32_t flips) {
  return slow | middle << shader::NOODLES_WALK_MIDDLE_SHIFT | flips << shader::NOODLES_WALK_FLIP_SHIFT;
}

// The walk that meets a grid of strands nearest first for a camera looking along `forward`: the axes
// by how closely they follow it, each from the end the camera looks from.
inline uint32_t nearestFirstWalk(glm::vec3 forward) {
  const glm::vec3 along = glm::abs(forward);
  uint32_t slow = 0, fast = 0;
  for (uint32_t axis = 1; axis < 3; ++axis) {
    if (along[axis] > along[slow]) slow = axis;
    if (along[axis] < along[fast]) fast = axis;
  }
  if (slow == fast) fast = (slow + 1) % 3;  // a view along no axis in particular: any order
  const uint32_t middle = 3 - slow - fast;
  const uint32_t flips = (forward.x < 0.0f ? 1u : 0u) | (forward.y < 0.0f ? 2u : 0u) | (forward.z < 0.0f ? 4u : 0u);
  return walkCode(slow, middle, flips);
}

// A chunk holding the whole grid is walked as the grid; a chunk of a split nest holds a run of
// strands in index order, z slowest, so it is walked as a row, from its far end when the camera looks
// down z (and the chunks are taken in that order too: chunksDescending).
inline bool chunksDescending(glm::vec3 forward) { return forward.z < 0.0f; }

inline StrandWalk chunkWalk(glm::uvec3 grid, uint32_t chunkStrands, glm::vec3 forward) {
  if (uint64_t(grid.x) * grid.y * grid.z == chunkStrands) return {grid, nearestFirstWalk(forward)};
  return {{chunkStrands, 1, 1}, walkCode(0, 1, chunksDescending(forward) ? 1u : 0u)};
}

// The chunk-local strand (x + X (y + Y z)) walked `position`-th.
inline uint32_t walkedStrand(uint32_t position, glm::uvec3 dims, uint32_t code) {
  const uint32_t slow = code & shader::NOODLES_WALK_AXIS_MASK;
  const uint32_t middle = code >> shader::NOODLES_WALK_MIDDLE_SHIFT & shader::NOODLES_WALK_AXIS_MASK;
  const uint32_t fast = 3 - slow - middle;
  glm::uvec3 c;
  c[fast] = position % dims[fast];
  const uint32_t rest = position / dims[fast];
  c[middle] = rest % dims[middle];
  c[slow] = rest / dims[middle];
  for (uint32_t axis = 0; axis < 3; ++axis)
    if (code >> (shader::NOODLES_WALK_FLIP_SHIFT + axis) & 1u) c[axis] = dims[axis] - 1 - c[axis];
  return c.x + dims.x * (c.y + dims.y * c.z);
}

}  // namespace vitrine::noodles
