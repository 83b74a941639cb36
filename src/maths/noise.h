#pragma once
// Gradient noise with its analytic gradient: a lattice of pseudo-random gradients hashed with pcg3d,
// blended with the quintic interpolant so value and gradient are both continuous across cells. The
// noodles scene's flows are made of it (maths/flow_field.h), neon's tubes swim in them and its ground
// ripples with it. Mirrored line for line by shaders/common/noise.glsl; tests/unit/noodles_test.cpp
// checks the gradient against finite differences.
#include "maths/hash.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace vitrine::maths {

struct NoiseSample {
  float value;
  glm::vec3 gradient;  // d value / d x, differentiated analytically
};

// The hash input for the cell whose lower corner is `cellCorner` (already floored). The int32 maximum
// is added so that cells either side of zero stay neighbours in the hash's input; the write-up's
// first version cast negative floats straight to unsigned, which folded every negative cell onto
// cell 0 and creased the field along the axes. The addition is unsigned so that it wraps
// identically in C++ (where signed overflow is undefined) and in GLSL.
inline glm::uvec3 latticeCell(glm::vec3 cellCorner) {
  return glm::uvec3(glm::ivec3(cellCorner)) + glm::uvec3(0x7fffffffu);
}

// A lattice gradient in [-1, 1)^3 built from the top 24 bits of each hash word: the conversion is
// exact in float, so the CPU reference and every GPU agree on it bit for bit. (The write-up's
// gradients lie in [0, 1]^3; centring them removes a lattice-aligned bias from the field.)
inline glm::vec3 latticeGradient(glm::uvec3 cell) {
  const glm::uvec3 bits = pcg3d(cell) >> 8u;
  return glm::vec3(bits) * (2.0f / 16777216.0f) - 1.0f;
}

// One corner's ramp dot(g, f - corner): its gradient with respect to x is g itself.
inline NoiseSample cornerRamp(glm::uvec3 cell, glm::vec3 f, glm::uvec3 corner) {
  const glm::vec3 g = latticeGradient(cell + corner);
  return {glm::dot(g, f - glm::vec3(corner)), g};
}

// Blends a towards b with weight w along one axis; dw is the weight's slope along that axis, so the
// blend's gradient there gains (b - a) * dw on top of the blended gradients.
inline NoiseSample blend(const NoiseSample& a, const NoiseSample& b, float w, float dw, int axis) {
  NoiseSample out{a.value + (b.value - a.value) * w, a.gradient + (b.gradient - a.gradient) * w};
  out.gradient[axis] += (b.value - a.value) * dw;
  return out;
}

inline NoiseSample gradientNoise(glm::vec3 x) {
  const glm::vec3 cellCorner = glm::floor(x);
  const glm::vec3 f = x - cellCorner;
  const glm::uvec3 cell = latticeCell(cellCorner);
  // Quintic interpolant 6f^5 - 15f^4 + 10f^3 and its slope: zero first and second derivatives at the
  // cell faces, so the gradient (which the curl is built from) has no kinks there.
  const glm::vec3 w = f * f * f * (f * (f * 6.0f - 15.0f) + 10.0f);
  const glm::vec3 dw = 30.0f * f * f * (f * (f - 2.0f) + 1.0f);

  const NoiseSample x00 = blend(cornerRamp(cell, f, {0, 0, 0}), cornerRamp(cell, f, {1, 0, 0}), w.x, dw.x, 0);
  const NoiseSample x10 = blend(cornerRamp(cell, f, {0, 1, 0}), cornerRamp(cell, f, {1, 1, 0}), w.x, dw.x, 0);
  const NoiseSample x01 = blend(cornerRamp(cell, f, {0, 0, 1}), cornerRamp(cell, f, {1, 0, 1}), w.x, dw.x, 0);
  const NoiseSample x11 = blend(cornerRamp(cell, f, {0, 1, 1}), cornerRamp(cell, f, {1, 1, 1}), w.x, dw.x, 0);
  const NoiseSample y0 = blend(x00, x10, w.y, dw.y, 1);
  const NoiseSample y1 = blend(x01, x11, w.y, dw.y, 1);
  return blend(y0, y1, w.z, dw.z, 2);
}

}  // namespace vitrine::maths
