// Push constants shared by tube.vert and tube.frag; mirrors TubePush in src/scenes/noodles/tube_pass.cpp.
#ifndef NOODLES_TUBE_PUSH_GLSL
#define NOODLES_TUBE_PUSH_GLSL

layout(push_constant) uniform Push {
  mat4 viewProjection;  // infinite reverse-Z
  vec3 eye;
  float radius;
  uint firstStrand;   // the chunk's first strand
  uint chunkStrands;  // strands in this chunk
  uint strands;       // in the whole grid, for colour
  uint colouring;
  uint segments;      // per strand
  uint stripe;        // 1: paint the side between ring corners 0 and 1
} pc;

#endif
