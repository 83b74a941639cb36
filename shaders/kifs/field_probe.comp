#version 460
// Evaluates the KIFS field at given points, so a test can hold the GLSL to its C++ mirror.
#extension GL_GOOGLE_include_directive : require
#include "kifs/field.glsl"

layout(local_size_x = 64) in;
layout(binding = 0, std430) readonly buffer Points { vec4 points[]; };  // xyz, w = stage
layout(binding = 1, std430) writeonly buffer Samples { vec4 samples[]; };  // distance, trap

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= points.length()) return;
  vec3 trap;
  float d = field(points[i].xyz, int(points[i].w), 1.0, trap);
  samples[i] = vec4(d, trap);
}
