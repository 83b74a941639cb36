// The tube rasteriser's blocks, one declaration for both sides (shaders/common/interop.h says how):
// the push block of raster.comp, raster_big.comp and shade.comp, which tube_view.h and the passes
// fill, and the big-segment counters, which raster_pass.cpp resets before each chunk.
#ifndef NOODLES_RASTER_BLOCKS_H
#define NOODLES_RASTER_BLOCKS_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
// Which segments a raster.comp dispatch takes (NoodlesRasterPush::phase). A big nest is drawn in two
// passes: every NOODLES_OCCLUDER_STRIDE-th strand first (spread through the nest, so they cover most
// of the screen), then tile_bound.comp keeps each tile's farthest held hit, then the other strands,
// which drop a segment at once when every tile its box touches already holds only nearer hits.
// Every fourth strand (H200, walked nearest first, 3x3 tiles: stride 8 -> 4 took 10^8 segments at
// 1080p from 7.50 to 7.27 ms and 10^7 at 3840x2160 from 13.73 to 11.87; stride 2: 8.57 and 13.25).
const uint NOODLES_RASTER_ALL = 0u;
const uint NOODLES_RASTER_OCCLUDERS = 1u;
const uint NOODLES_RASTER_REST = 2u;
const uint NOODLES_OCCLUDER_STRIDE = 4u;
const uint NOODLES_BOUND_TILE = 8u;  // pixels a side of the tiles tile_bound.comp bounds
// Listed big segments (16 MiB): past it raster.comp casts a big box itself.
const uint NOODLES_BIG_LIST_CAPACITY = 1u << 22;

// NoodlesRasterPush::walk (src/scenes/noodles/strand_walk.h): the axis walked slowest in bits 0-1, the
// middle one from NOODLES_WALK_MIDDLE_SHIFT, the axes walked from their far end from _FLIP_SHIFT.
const uint NOODLES_WALK_AXIS_MASK = 3u;
const uint NOODLES_WALK_MIDDLE_SHIFT = 2u;
const uint NOODLES_WALK_FLIP_SHIFT = 4u;

// The camera as rays (capsule.glsl's ScreenView), the look and the chunk. std430: each vec3 starts a
// 16-byte slot, which the float after it shares.
struct NoodlesRasterPush {
  vec3 eye;
  float tubeRadius;
  vec3 right;
  float tanHalfX;
  vec3 up;
  float tanHalfY;
  vec3 forward;
  float nearPlane;
  vec2 pixels;             // the target's size (the samples a pixel specialise the pipeline: raster_push.glsl)
  uint segmentsPerStrand;
  uint totalStrands;       // in the whole grid, for colour
  uint colouring;          // COLOURING_GRADIENT, COLOURING_HSV or COLOURING_GREY
  uint stripe;             // 1: paint the side between frame angles 0 and 45 degrees
  uint firstStrand;        // the chunk's first strand
  uint chunkStrands;       // strands in this chunk
  uint invocationsPerRow;  // raster.comp's 2D dispatch: invocations in one row of workgroups
  uint accumulate;         // shade.comp: 0 for the first chunk (writes), 1 after (adds)
  uint phase;              // NOODLES_RASTER_ALL, _OCCLUDERS or _REST
  uint phaseStrands;       // the chunk's strands this phase takes
  uint tilesPerRow;        // tile_bound.comp's tiles across the target
  uint walkX, walkY;       // the chunk's strands as a grid, x fastest: walkX x walkY x the rest
  uint walk;               // the order raster.comp takes them in (NOODLES_WALK_*)
};

// tile_bound.comp's push block.
struct NoodlesTileBoundPush {
  uvec2 pixels;          // the target's size
  uint samplesPerPixel;  // keys a pixel: 1 or 4
  uint tilesPerRow;
};

// The big-segment pass's indirect dispatch (a VkDispatchIndirectCommand: raster.comp adds a workgroup
// per listed segment, up to MAX_BIG_GROUPS), then how many segments it listed.
struct NoodlesBigSegmentCounters {
  uint groupsX;
  uint groupsY;
  uint groupsZ;
  uint listed;
};
VITRINE_SHARED_END

#endif
