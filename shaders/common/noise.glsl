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

// A corner's ramp dot(g, f - corner) and its gradient g.
NoiseSample cornerRamp(vec3 g, vec3 f, uvec3 corner) {
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

// The noise at f (the point's place in its cell, 0..1) from the cell's eight corner gradients, gXYZ
// for the corner at (X, Y, Z): gradientNoise hashes them, noodles' bake shares them across a workgroup.
NoiseSample noiseFromCorners(vec3 f, vec3 g000, vec3 g100, vec3 g010, vec3 g110, vec3 g001, vec3 g101, vec3 g011,
                             vec3 g111) {
  NOISE_PRECISE vec3 w = f * f * f * (f * (f * 6.0 - 15.0) + 10.0);
  NOISE_PRECISE vec3 dw = 30.0 * f * f * (f * (f - 2.0) + 1.0);
  NoiseSample x00 = blend(cornerRamp(g000, f, uvec3(0, 0, 0)), cornerRamp(g100, f, uvec3(1, 0, 0)), w.x, dw.x, 0);
  NoiseSample x10 = blend(cornerRamp(g010, f, uvec3(0, 1, 0)), cornerRamp(g110, f, uvec3(1, 1, 0)), w.x, dw.x, 0);
  NoiseSample x01 = blend(cornerRamp(g001, f, uvec3(0, 0, 1)), cornerRamp(g101, f, uvec3(1, 0, 1)), w.x, dw.x, 0);
  NoiseSample x11 = blend(cornerRamp(g011, f, uvec3(0, 1, 1)), cornerRamp(g111, f, uvec3(1, 1, 1)), w.x, dw.x, 0);
  NoiseSample y0 = blend(x00, x10, w.y, dw.y, 1);
  NoiseSample y1 = blend(x01, x11, w.y, dw.y, 1);
  return blend(y0, y1, w.z, dw.z, 2);
}

NoiseSample gradientNoise(vec3 x) {
  vec3 cellCorner = floor(x);
  NOISE_PRECISE vec3 f = x - cellCorner;
  uvec3 cell = latticeCell(cellCorner);
  return noiseFromCorners(f, latticeGradient(cell), latticeGradient(cell + uvec3(1, 0, 0)),
                          latticeGradient(cell + uvec3(0, 1, 0)), latticeGradient(cell + uvec3(1, 1, 0)),
                          latticeGradient(cell + uvec3(0, 0, 1)), latticeGradient(cell + uvec3(1, 0, 1)),
                          latticeGradient(cell + uvec3(0, 1, 1)), latticeGradient(cell + uvec3(1, 1, 1)));
}

#endif
