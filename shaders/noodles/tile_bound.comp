#version 460
// Between the occluders and the rest of a big nest (raster_blocks.h): a workgroup a tile of 8x8
// pixels keeps the farthest depth any of the tile's samples holds. An empty sample holds all ones,
// so a tile not yet covered everywhere bounds nothing.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "noodles/raster_blocks.h"

layout(local_size_x = NOODLES_BOUND_TILE, local_size_y = NOODLES_BOUND_TILE) in;  // a tile
layout(binding = 0, std430) readonly buffer Visibility { uint64_t keys[]; };
layout(binding = 1, std430) writeonly buffer TileFar { uint tileFar[]; };
layout(push_constant) uniform Push { NoodlesTileBoundPush pc; };

shared uint farthest;

void main() {
  if (gl_LocalInvocationIndex == 0u) farthest = 0u;
  barrier();
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (all(lessThan(pixel, pc.pixels))) {
    uint first = (pixel.y * pc.pixels.x + pixel.x) * pc.samplesPerPixel;
    uint far = 0u;
    for (uint q = 0u; q < pc.samplesPerPixel; ++q) far = max(far, uint(keys[first + q] >> 32));
    atomicMax(farthest, far);
  }
  barrier();
  if (gl_LocalInvocationIndex == 0u) tileFar[gl_WorkGroupID.y * pc.tilesPerRow + gl_WorkGroupID.x] = farthest;
}
