// The statistics pass's blocks, one declaration for both sides (shaders/common/interop.h says how):
// bloom_scene.cpp pushes the thresholds, stats.comp counts into the counts buffer, and the scene
// reads the counts back a few frames later (gpu/readback_ring.h).
#ifndef BLOOM_STATS_BLOCKS_H
#define BLOOM_STATS_BLOCKS_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
const uint kBloomStatsColumn = 16;  // voxels along z one statistics invocation counts

// The event thresholds a voxel of the interior is counted past (strictly above), in order.
struct BloomStatsThresholds {
  float amber;
  float rose;
  float crimson;
  float climax;
};

// Zeroed before each pass; every workgroup adds its sums with one atomic per counter.
struct BloomLatticeCounts {
  uint interior;  // the crystal's voxels inside its core (bloom_math.h: insideCore)
  uint above[4];  // of those, past the amber, rose, crimson and climax thresholds
  uint peakBits;  // the largest value over the whole crystal, as float bits (positive floats order as
                  // their bits do, so an integer atomicMax finds it)
};
VITRINE_SHARED_END

#endif
