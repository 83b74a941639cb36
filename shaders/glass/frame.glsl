// The glass scene's per-frame block (glass/frame_block.h, which C++ fills), and what follows from it:
// the camera's rays and projection, and the panorama's lookup.
//
// A read-only storage buffer rather than a uniform block, on purpose: Mesa 22's lavapipe "inlines"
// uniform-block values that steer branches of a large shader, compiling a fresh copy of the shader at
// every bind of its pipeline and never freeing it. With a uniform block the spectral pass grew the
// process by about 1 MiB a frame (3.8 MiB on the raster path) and recompiled every frame; storage
// buffers are never inlined. On real GPUs a read-only, uniformly indexed buffer costs the same here.
#ifndef GLASS_FRAME_GLSL
#define GLASS_FRAME_GLSL
#include "glass/frame_block.h"

layout(std430, set = 0, binding = 0) restrict readonly buffer Frame { GlassFrame F; };

const float PI = 3.14159265358979;

// The world position at the z = 0 plane under a pixel (origin top-left, y down), and the primary ray.
vec3 pixelToWorld(vec2 pixel) {
  vec2 ndc = pixel / F.viewPixels * 2.0 - 1.0;
  return vec3(ndc.x * 0.5 * F.viewWorld.x, -ndc.y * 0.5 * F.viewWorld.y, 0.0);
}
void primaryRay(vec2 pixel, out vec3 origin, out vec3 dir) {
  vec3 p = pixelToWorld(pixel);
  if (F.orthographic != 0u) {
    origin = vec3(p.xy, F.eye.z);
    dir = vec3(0.0, 0.0, -1.0);
  } else {
    origin = F.eye;
    dir = normalize(p - origin);
  }
}
// Where a world point lands on the screen, in pixels.
vec2 worldToPixel(vec3 p) {
  vec4 clip = F.viewProjection * vec4(p, 1.0);
  vec2 ndc = clip.xy / clip.w;
  return (ndc * 0.5 + 0.5) * F.viewPixels;
}

// Equirectangular lookup, the original's convention (src/scenes/glass/studio.h): longitude atan2(d.x, d.z)
// plus the environment rotation, +y up; an unturned panorama shows its u = 0 seam straight ahead.
vec2 equirectUv(vec3 d) {
  float phi = atan(d.x, d.z) + F.envRotation;
  float theta = acos(clamp(d.y, -1.0, 1.0));
  return vec2(fract(phi / (2.0 * PI) + 0.5), theta / PI);
}

#endif
