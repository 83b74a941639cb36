#pragma once
// pcg3d (Jarzynski & Olano, "Hash Functions for GPU Rendering", 2020): three 32-bit words in, three
// well-mixed words out. Integer-only, so the CPU, lavapipe and any GPU agree bit for bit.
// Mirrored by shaders/common/hash.glsl.
#include <glm/vec3.hpp>

#include <cstdint>

namespace vitrine::maths {

inline glm::uvec3 pcg3d(glm::uvec3 v) {
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

// A uniform float in [0, 1): the top 24 bits, so every value is exact in float.
inline float hash01(glm::uvec3 v) { return float(pcg3d(v).x >> 8) * (1.0f / 16777216.0f); }

}  // namespace vitrine::maths
