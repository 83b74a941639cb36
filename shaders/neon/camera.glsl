// The neon scene's per-frame block; mirrors NeonFrame in src/scenes/neon/neon_scene.cpp.
#ifndef NEON_CAMERA_GLSL
#define NEON_CAMERA_GLSL

layout(std140, set = 0, binding = 0) uniform Frame {
  mat4 viewProjection;  // reverse-Z, infinitely far
  vec4 eye;             // xyz; w: the projection's near distance
  vec4 colourA;         // linear rgb; w: glow
  vec4 colourB;         // linear rgb; w: tube radius
  uvec4 counts;         // chains, particles per chain, 0, 0
} F;

#endif
