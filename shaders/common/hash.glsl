// pcg3d and a [0,1) float from it; mirrors src/maths/hash.h.
#ifndef VITRINE_HASH_GLSL
#define VITRINE_HASH_GLSL

uvec3 pcg3d(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z;
  v.y += v.z * v.x;
  v.z += v.x * v.y;
  return v;
}

float hash01(uvec3 v) { return float(pcg3d(v).x >> 8) * (1.0 / 16777216.0); }

#endif
