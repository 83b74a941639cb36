// The glass scene's optics; mirrors src/scenes/glass/optics.h function for function, with the same
// constants and order of operations (the comments there say why).
#ifndef GLASS_OPTICS_GLSL
#define GLASS_OPTICS_GLSL

#include "common/hash.glsl"

// Snell's law, eta = n_t / n_i, n facing against d. ok = false at total internal reflection.
vec3 refractDir(vec3 d, vec3 n, float eta, out bool ok) {
  float cosI = -dot(d, n);
  float k = 1.0 - (1.0 - cosI * cosI) / (eta * eta);
  ok = k >= 0.0;
  return ok ? normalize(d / eta + (cosI / eta - sqrt(k)) * n) : vec3(0.0);
}

vec3 reflectDir(vec3 d, vec3 n) { return d - 2.0 * dot(d, n) * n; }

float fresnelSchlick(float cosI, float eta) {
  float r0 = (eta - 1.0) / (eta + 1.0);
  float f0 = r0 * r0;
  float m = 1.0 - clamp(cosI, 0.0, 1.0);
  return f0 + (1.0 - f0) * m * m * m * m * m;
}

float fresnelDielectric(float cosI, float eta) {
  cosI = clamp(cosI, 0.0, 1.0);
  float sinT2 = (1.0 - cosI * cosI) / (eta * eta);
  if (sinT2 >= 1.0) return 1.0;
  float cosT = sqrt(1.0 - sinT2);
  float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5 * (rs * rs + rp * rp);
}

// --- Index of refraction

const float kLambdaH = 404.66;
const float kLambdaG = 435.83;
const float kLambdaF = 486.13;
const float kLambdaE = 546.07;
const float kLambdaD = 587.56;
const float kLambdaC = 656.27;
const float kMinAbbe = 0.5;

float cauchyIor(float lambdaNm, float nd, float vd) {
  if (!(vd > 0.0)) return nd;
  vd = max(vd, kMinAbbe);
  return max(nd + (nd - 1.0) / vd * (523655.0 / (lambdaNm * lambdaNm) - 1.5168), 1.0);
}

float sellmeierIor(float lambdaNm, vec3 b, vec3 c) {
  float l = lambdaNm * 0.001;
  float l2 = l * l;
  float n2 = 1.0 + b.x * l2 / (l2 - c.x) + b.y * l2 / (l2 - c.y) + b.z * l2 / (l2 - c.z);
  return sqrt(max(n2, 1.0));
}

// --- Colour matching (Wyman, Sloan & Shirley 2013, multi-lobe fit of CIE 1931 2-degree)

float cieLobe(float x, float mu, float s1, float s2) {
  float t = (x - mu) / (x < mu ? s1 : s2);
  return exp(-0.5 * t * t);
}

vec3 cieXyz(float lambdaNm) {
  float x = 1.056 * cieLobe(lambdaNm, 599.8, 37.9, 31.0) + 0.362 * cieLobe(lambdaNm, 442.0, 16.0, 26.7) -
            0.065 * cieLobe(lambdaNm, 501.1, 20.4, 26.2);
  float y = 0.821 * cieLobe(lambdaNm, 568.8, 46.9, 40.5) + 0.286 * cieLobe(lambdaNm, 530.9, 16.3, 31.1);
  float z = 1.217 * cieLobe(lambdaNm, 437.0, 11.8, 36.0) + 0.681 * cieLobe(lambdaNm, 459.0, 26.0, 13.8);
  return vec3(x, y, z);
}

// IEC 61966-2-1's four-decimal XYZ -> linear sRGB (D65) matrix.
vec3 xyzToLinearSrgb(vec3 c) {
  return vec3(3.2406 * c.x - 1.5372 * c.y - 0.4986 * c.z, -0.9689 * c.x + 1.8758 * c.y + 0.0415 * c.z,
              0.0557 * c.x - 0.2040 * c.y + 1.0570 * c.z);
}

vec3 spectralWeight(float lambdaNm) { return max(xyzToLinearSrgb(cieXyz(lambdaNm)), vec3(0.0)); }

// --- Wavelength sampling

const float kLambdaMin = 380.0;
const float kLambdaMax = 700.0;
const float kHeroLambdaFixed = 550.0;
const uint kGoldenStep = 2654435769u;

float stratifiedLambda(int i, int n, float u) {
  return kLambdaMin + (float(i) + u) * (kLambdaMax - kLambdaMin) / float(n);
}

vec3 spectralWeightSum(int n, float u) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < n; ++i) sum += spectralWeight(stratifiedLambda(i, n, u));
  return sum;
}

float goldenPhase(uint start, uint frame) { return float((start + frame * kGoldenStep) >> 8) * (1.0 / 16777216.0); }

float spectralPhase(uvec2 pixel, uint frame, uint seed, bool jitter) {
  return jitter ? goldenPhase(pcg3d(uvec3(pixel, seed)).x, frame) : 0.5;
}

float heroLambda(uint frame, uint seed, bool jitter) {
  if (!jitter) return kHeroLambdaFixed;
  return kLambdaMin + (kLambdaMax - kLambdaMin) * goldenPhase(pcg3d(uvec3(~0u, ~0u, seed)).x, frame);
}

// --- Tone mapping (Khronos PBR Neutral)

vec3 filmic(vec3 color) {
  const float kStart = 0.8 - 0.04;
  const float kDesaturation = 0.15;
  float x = min(color.x, min(color.y, color.z));
  float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  color -= offset;
  float peak = max(color.x, max(color.y, color.z));
  if (peak < kStart) return color;
  float d = 1.0 - kStart;
  float newPeak = 1.0 - d * d / (peak + d - kStart);
  color *= newPeak / peak;
  float g = 1.0 - 1.0 / (kDesaturation * (peak - newPeak) + 1.0);
  return mix(color, vec3(newPeak), g);
}

#endif
