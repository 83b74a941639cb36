// Push constants of the crystal pass; mirrors CrystalPush in src/scenes/bloom/bloom_scene.cpp.
#include "crystal.glsl"
layout(push_constant) uniform Push {
  mat4 viewProjection;
  vec3 eye;
  float time;
  vec3 tint;         // the crystal's state colour (bloom_math.h: flipColour), linear
  uint seed;
  uint frame;        // 0 under reduced motion: the jitter holds still
  uint traceSteps;   // sphere-trace budget to the entry (48)
  uint samples;      // volume samples to the exit (56)
  float shimmer;     // climax: 0..1 (0 under reduced motion)
} pc;
