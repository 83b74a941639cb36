// The neon scene's per-frame block (NeonFrame, shared with the C++ in neon/frame.h) as F, and the rays
// it defines.
#ifndef NEON_CAMERA_GLSL
#define NEON_CAMERA_GLSL
#include "neon/frame.h"

layout(std140, set = 0, binding = 0) uniform Frame { NeonFrame F; };

// The primary ray through a pixel (origin top-left, y down).
vec3 pixelRay(vec2 pixel) {
  const vec2 ndc = pixel / vec2(F.frameWidth, F.frameHeight) * 2.0 - 1.0;
  return normalize(F.forward + ndc.x * F.right - ndc.y * F.up);
}

#endif
