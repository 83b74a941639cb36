// The order the tube rasteriser takes strands in (scenes/noodles/strand_walk.h, mirrored by
// shaders/noodles/raster_push.glsl's walkedStrand): every walk visits each strand once, and the one
// chosen for a view meets the grid nearest first.
#include "scenes/noodles/strand_walk.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <vector>

namespace vitrine::noodles {
namespace {

// Every axis order and every set of flips.
std::vector<uint32_t> everyWalk() {
  std::vector<uint32_t> codes;
  for (uint32_t slow = 0; slow < 3; ++slow)
    for (uint32_t middle = 0; middle < 3; ++middle)
      if (middle != slow)
        for (uint32_t flips = 0; flips < 8; ++flips) codes.push_back(walkCode(slow, middle, flips));
  return codes;
}

TEST(NoodlesWalk, EveryWalkVisitsEachStrandOnce) {
  for (const glm::uvec3 dims : {glm::uvec3(4, 3, 5), glm::uvec3(1, 7, 2), glm::uvec3(6, 1, 1), glm::uvec3(2, 2, 2)}) {
    const uint32_t count = dims.x * dims.y * dims.z;
    for (const uint32_t code : everyWalk()) {
      std::vector<int> visits(count, 0);
      for (uint32_t position = 0; position < count; ++position) {
        const uint32_t strand = walkedStrand(position, dims, code);
        ASSERT_LT(strand, count) << "code " << code;
        ++visits[strand];
      }
      for (uint32_t strand = 0; strand < count; ++strand)
        EXPECT_EQ(visits[strand], 1) << "code " << code << " strand " << strand;
    }
  }
}

TEST(NoodlesWalk, TheIdentityWalkIsIndexOrder) {
  const glm::uvec3 dims(4, 3, 5);
  for (uint32_t position = 0; position < 60; ++position)
    EXPECT_EQ(walkedStrand(position, dims, walkCode(2, 1, 0)), position);
}

// Seeds on the grid, walked for a camera looking along `forward`: the strands' depths along it, slab
// by slab of the slowest axis (the strands in flight together), rise from slab to slab, and the
// slowest axis is the one the view follows most.
TEST(NoodlesWalk, TheChosenWalkMeetsTheGridNearestFirst) {
  const glm::uvec3 grid(6, 5, 4);
  const uint32_t count = grid.x * grid.y * grid.z;
  for (const glm::vec3 forward : {glm::vec3(1, 0.2f, -0.3f), glm::vec3(-0.1f, -1, 0.4f), glm::vec3(0.3f, 0.5f, -2),
                                  glm::vec3(-0.7f, 0.6f, 0.1f), glm::vec3(0.2f, -0.3f, 1)}) {
    const StrandWalk walk = chunkWalk(grid, count, glm::normalize(forward));
    ASSERT_EQ(walk.dims, grid);
    const uint32_t slow = walk.code & shader::NOODLES_WALK_AXIS_MASK;
    const glm::vec3 along = glm::abs(forward);
    for (uint32_t axis = 0; axis < 3; ++axis) EXPECT_GE(along[slow], along[axis]);
    const uint32_t slabs = grid[slow], perSlab = count / slabs;
    float previous = -1e30f;
    for (uint32_t slab = 0; slab < slabs; ++slab) {
      float depth = 0.0f;
      for (uint32_t i = 0; i < perSlab; ++i) {
        const uint32_t strand = walkedStrand(slab * perSlab + i, walk.dims, walk.code);
        const glm::vec3 seed(strand % grid.x, strand / grid.x % grid.y, strand / (grid.x * grid.y));
        depth += glm::dot(seed, forward) / float(perSlab);
      }
      EXPECT_GT(depth, previous) << "slab " << slab;
      previous = depth;
    }
  }
}

// A chunk of a split nest is a run of strands in index order (z slowest): walked as a row, from its
// far end when the camera looks down z, and the chunks are taken in that order too.
TEST(NoodlesWalk, AChunkOfASplitNestIsWalkedAsARowAlongZ) {
  const glm::uvec3 grid(8, 8, 8);
  const StrandWalk up = chunkWalk(grid, 100, {0.1f, 0.2f, 0.97f});
  EXPECT_EQ(up.dims, glm::uvec3(100, 1, 1));
  EXPECT_EQ(walkedStrand(0, up.dims, up.code), 0u);
  EXPECT_FALSE(chunksDescending({0.1f, 0.2f, 0.97f}));
  const StrandWalk down = chunkWalk(grid, 100, {0.1f, 0.2f, -0.97f});
  EXPECT_EQ(walkedStrand(0, down.dims, down.code), 99u);
  EXPECT_EQ(walkedStrand(99, down.dims, down.code), 0u);
  EXPECT_TRUE(chunksDescending({0.1f, 0.2f, -0.97f}));
}

}  // namespace
}  // namespace vitrine::noodles
