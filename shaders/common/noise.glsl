// Gradient noise with its analytic gradient; mirrors src/maths/noise.h.
#ifndef VITRINE_NOISE_GLSL
#define VITRINE_NOISE_GLSL
#include "common/hash.glsl"

// A shader that must match its CPU reference bit for bit (neon's chains, integrated frame after frame)
// defines NOISE_EXACT before including this: every local below is then `precise` (SPIR-V
// NoContraction), so no driver fuses a multiply into an add, and what is left (add, subtract,
// multiply, floor, conversions) is correctly rounded on every Vulkan device. glslang does not carry
// `precise` into called functions or their arguments, hence a qualifier on each local and no dot().
// Noodles, which re-integrates its streamlines from their seeds every frame, keeps the fused forms.
#ifdef NOISE_EXACT
#define NOISE_PRECISE precise
#else
#define NOISE_PRECISE
#endif

struct NoiseSample {
  float value;
  vec3 gradient;
};

// The int32 maximum keeps cells either side of zero neighbours in the hash input (see noise.h).
uvec3 latticeCell(vec3 cellCorner) { return uvec3(ivec3(cellCorner)) + uvec3(0x7fffffffu); }

// Top 24 bits of each hash word: exact in float, identical on CPU and GPU.
vec3 latticeGradient(uvec3 cell) {
  uvec3 bits = pcg3d(cell) >> 8u;
  NOISE_PRECISE vec3 g = vec3(bits) * (2.0 / 16777216.0) - 1.0;
  return g;
}

NoiseSample cornerRamp(uvec3 cell, vec3 f, uvec3 corner) {
  vec3 g = latticeGradient(cell + corner);
  NOISE_PRECISE vec3 d = f - vec3(corner);
  NOISE_PRECISE float ramp = g.x * d.x + g.y * d.y + g.z * d.z;  // dot(g, d) in glm's order
  return NoiseSample(ramp, g);
}

NoiseSample blend(NoiseSample a, NoiseSample b, float w, float dw, int axis) {
  NOISE_PRECISE NoiseSample blended =
      NoiseSample(a.value + (b.value - a.value) * w, a.gradient + (b.gradient - a.gradient) * w);
  blended.gradient[axis] += (b.value - a.value) * dw;
  return blended;
}

NoiseSample gradientNoise(vec3 x) {
  vec3 cellCorner = floor(x);
  NOISE_PRECISE vec3 f = x - cellCorner;
  uvec3 cell = latticeCell(cellCorner);
  NOISE_PRECISE vec3 w = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  NOISE_PRECISE vec3 dw = 30.0 * f * f * (f * (f - 2.0) + 1.0);

  NoiseSample x00 = blend(cornerRamp(cell, f, uvec3(0, 0, 0)), cornerRamp(cell, f, uvec3(1, 0, 0)), w.x, dw.x, 0);
  NoiseSample x10 = blend(cornerRamp(cell, f, uvec3(0, 1, 0)), cornerRamp(cell, f, uvec3(1, 1, 0)), w.x, dw.x, 0);
  NoiseSample x01 = blend(cornerRamp(cell, f, uvec3(0, 0, 1)), cornerRamp(cell, f, uvec3(1, 0, 1)), w.x, dw.x, 0);
  NoiseSample x11 = blend(cornerRamp(cell, f, uvec3(0, 1, 1)), cornerRamp(cell, f, uvec3(1, 1, 1)), w.x, dw.x, 0);
  NoiseSample y0 = blend(x00, x10, w.y, dw.y, 1);
  NoiseSample y1 = blend(x01, x11, w.y, dw.y, 1);
  return blend(y0, y1, w.z, dw.z, 2);
}

#endif
