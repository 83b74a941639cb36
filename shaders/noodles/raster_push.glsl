// Push constants of the tube rasteriser's passes (raster.comp, raster_big.comp, shade.comp);
// mirrors RasterPush in src/scenes/noodles/raster_push.h.
#ifndef NOODLES_RASTER_PUSH_GLSL
#define NOODLES_RASTER_PUSH_GLSL
#include "noodles/capsule.glsl"

layout(push_constant) uniform Push {
  vec3 eye;
  float radius;
  vec3 right;
  float tanHalfX;
  vec3 up;
  float tanHalfY;
  vec3 forward;
  float nearPlane;
  vec2 pixels;           // the target's size
  uint samplesPerAxis;   // 2: four samples a pixel, one in each quarter; 1: one at the centre
  uint segments;         // per strand
  uint strands;          // in the whole grid, for colour
  uint colouring;
  uint stripe;           // 1: paint the side between frame angles 0 and 45 degrees
  uint bigCapacity;      // entries the big-segment list holds
  uint firstStrand;      // the chunk's first strand
  uint chunkStrands;     // strands in this chunk
  uint invocationsPerRow;  // raster.comp's 2D dispatch: invocations in one row of workgroups
  uint accumulate;       // shade.comp: 0 for the first chunk (writes), 1 after (adds)
} pc;

ScreenView screenView() {
  return ScreenView(pc.eye, pc.right, pc.up, pc.forward, pc.tanHalfX, pc.tanHalfY, pc.nearPlane, pc.pixels);
}

// Segments run node-major, like the nodes, so neighbouring invocations read neighbouring records:
// chunk-local segment `index` is segment index / chunkStrands of strand index % chunkStrands.
uint chunkSegments() { return pc.chunkStrands * pc.segments; }
// The segment's name in the visibility buffer: unique across chunks.
uint segmentId(uint index) { return pc.firstStrand * pc.segments + index; }

#endif
