#pragma once
// The glass scene's optics in plain C++: what the unit tests check and shaders/glass/optics.glsl
// mirrors function for function (same names, constants and order of operations, so the two agree to
// float rounding). Wavelengths are in nanometres; eta is always n_transmitted / n_incident.
#include "maths/hash.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

namespace vitrine::glass {

// Snell's law for a unit direction d meeting a surface whose unit normal n faces against d
// (dot(d, n) < 0), going from index n_i into n_t with eta = n_t / n_i. None at total internal reflection.
inline std::optional<glm::vec3> refractDir(glm::vec3 d, glm::vec3 n, float eta) {
  const float cosI = -glm::dot(d, n);
  const float k = 1.0f - (1.0f - cosI * cosI) / (eta * eta);
  if (k < 0.0f) return std::nullopt;
  return glm::normalize(d / eta + (cosI / eta - std::sqrt(k)) * n);
}

inline glm::vec3 reflectDir(glm::vec3 d, glm::vec3 n) { return d - 2.0f * glm::dot(d, n) * n; }

// Schlick's approximation of the reflectance at an interface (the original's per-wavelength Fresnel).
// cosI: cosine of the angle of incidence on the incident side.
inline float fresnelSchlick(float cosI, float eta) {
  const float r0 = (eta - 1.0f) / (eta + 1.0f);
  const float f0 = r0 * r0;
  const float m = 1.0f - glm::clamp(cosI, 0.0f, 1.0f);
  return f0 + (1.0f - f0) * m * m * m * m * m;
}

// The exact unpolarised dielectric reflectance (mean of s and p), 1 at total internal reflection.
inline float fresnelDielectric(float cosI, float eta) {
  cosI = glm::clamp(cosI, 0.0f, 1.0f);
  const float sinT2 = (1.0f - cosI * cosI) / (eta * eta);
  if (sinT2 >= 1.0f) return 1.0f;
  const float cosT = std::sqrt(1.0f - sinT2);
  const float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  const float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5f * (rs * rs + rp * rp);
}

// --- Index of refraction ---------------------------------------------------------------------------

// Fraunhofer lines (nm) that catalogues quote indices at: n_d is the helium d line, V_d uses F and C.
inline constexpr float kLambdaH = 404.66f;  // mercury h
inline constexpr float kLambdaG = 435.83f;  // mercury g
inline constexpr float kLambdaF = 486.13f;  // hydrogen F
inline constexpr float kLambdaE = 546.07f;  // mercury e
inline constexpr float kLambdaD = 587.56f;  // helium d
inline constexpr float kLambdaC = 656.27f;  // hydrogen C

// Below this Abbe number the Cauchy slope is held (V_d = 0.5 already spreads n by more than n_d - 1 over
// the visible range). With it, n stays above 1 everywhere in 380..700 nm, so the floor only acts in the
// infrared. V_d <= 0 means "no dispersion", as in glTF.
inline constexpr float kMinAbbe = 0.5f;

// KHR_materials_dispersion's two-term Cauchy law fitted to (n_d, V_d): n = A + B / lambda^2 with B chosen so
// that n_F - n_C = (n_d - 1) / V_d (523655 = 1 / (1/486.13^2 - 1/656.27^2), in nm^2) and A so that
// n(587.56) = n_d (1.5168 = 523655 / 587.56^2, to the four places the extension writes). Floored at 1.
inline float cauchyIor(float lambdaNm, float nd, float vd) {
  if (!(vd > 0.0f)) return nd;
  vd = glm::max(vd, kMinAbbe);
  return glm::max(nd + (nd - 1.0f) / vd * (523655.0f / (lambdaNm * lambdaNm) - 1.5168f), 1.0f);
}

// A three-term Sellmeier law, n^2 = 1 + sum B_i L^2 / (L^2 - C_i) with L in micrometres and C_i in um^2.
struct Sellmeier {
  float B[3];
  float C[3];
};

// Valid between the material's absorption resonances (every C_i here lies outside 380..700 nm); floored
// at 1 like cauchyIor so a wavelength on the wrong side of a resonance never yields a NaN.
inline float sellmeierIor(float lambdaNm, glm::vec3 b, glm::vec3 c) {
  const float l = lambdaNm * 0.001f;
  const float l2 = l * l;
  const float n2 = 1.0f + b.x * l2 / (l2 - c.x) + b.y * l2 / (l2 - c.y) + b.z * l2 / (l2 - c.z);
  return std::sqrt(glm::max(n2, 1.0f));
}
inline float sellmeierIor(float lambdaNm, const Sellmeier& s) {
  return sellmeierIor(lambdaNm, {s.B[0], s.B[1], s.B[2]}, {s.C[0], s.C[1], s.C[2]});
}

// --- Colour matching --------------------------------------------------------------------------------

// One lobe of a piecewise Gaussian: width s1 left of the peak mu, s2 right of it.
inline float cieLobe(float x, float mu, float s1, float s2) {
  const float t = (x - mu) / (x < mu ? s1 : s2);
  return std::exp(-0.5f * t * t);
}

// CIE 1931 2-degree colour matching functions (x-bar, y-bar, z-bar) at lambda, by the multi-lobe
// piecewise-Gaussian fit of Wyman, Sloan & Shirley, "Simple Analytic Approximations to the CIE XYZ Color
// Matching Functions", JCGT 2(2), 2013. No table: the shader evaluates the same seven lobes.
inline glm::vec3 cieXyz(float lambdaNm) {
  const float x = 1.056f * cieLobe(lambdaNm, 599.8f, 37.9f, 31.0f) + 0.362f * cieLobe(lambdaNm, 442.0f, 16.0f, 26.7f) -
                  0.065f * cieLobe(lambdaNm, 501.1f, 20.4f, 26.2f);
  const float y = 0.821f * cieLobe(lambdaNm, 568.8f, 46.9f, 40.5f) + 0.286f * cieLobe(lambdaNm, 530.9f, 16.3f, 31.1f);
  const float z = 1.217f * cieLobe(lambdaNm, 437.0f, 11.8f, 36.0f) + 0.681f * cieLobe(lambdaNm, 459.0f, 26.0f, 13.8f);
  return {x, y, z};
}

// XYZ to linear sRGB (D65), with the four-decimal matrix that IEC 61966-2-1 publishes, not the inverse
// re-derived from the primaries and white point (they differ by up to 2e-4 per entry).
inline glm::vec3 xyzToLinearSrgb(glm::vec3 c) {
  return {3.2406f * c.x - 1.5372f * c.y - 0.4986f * c.z, -0.9689f * c.x + 1.8758f * c.y + 0.0415f * c.z,
          0.0557f * c.x - 0.2040f * c.y + 1.0570f * c.z};
}

// How much a sample at lambda adds to each linear sRGB channel. Negative lobes (spectral colours lie
// outside the sRGB gamut) are dropped: a photo pixel can only be brightened by light it carries.
inline glm::vec3 spectralWeight(float lambdaNm) { return glm::max(xyzToLinearSrgb(cieXyz(lambdaNm)), glm::vec3(0.0f)); }

// --- Wavelength sampling ----------------------------------------------------------------------------

inline constexpr float kLambdaMin = 380.0f;
inline constexpr float kLambdaMax = 700.0f;
inline constexpr float kHeroLambdaFixed = 550.0f;  // Approx mode's wavelength with jitter off
inline constexpr std::array<int, 5> kSampleCounts = {3, 8, 16, 32, 64};
// 2^32 / golden ratio: adding it each frame steps a 32-bit fixed-point phase by the golden-ratio
// conjugate 0.6180339887..., the additive sequence that spreads successive frames most evenly.
inline constexpr uint32_t kGoldenStep = 2654435769u;

// Sample i of n: stratum i of [380, 700) split into n equal parts, at fraction u in [0, 1) across it.
// Written (i + u) * 320 / n so the stratum edges (u = 0) are correctly rounded and the last edge is 700.
inline float stratifiedLambda(int i, int n, float u) {
  return kLambdaMin + (float(i) + u) * (kLambdaMax - kLambdaMin) / float(n);
}

// Sum of spectralWeight over the n stratified samples at phase u. A pixel that adds weight * colour per
// sample and divides by this sum per channel reproduces an undisturbed background exactly.
inline glm::vec3 spectralWeightSum(int n, float u) {
  glm::vec3 sum(0.0f);
  for (int i = 0; i < n; ++i) sum += spectralWeight(stratifiedLambda(i, n, u));
  return sum;
}

// fract(start / 2^32 + frame * 0.618...) in 32-bit fixed point, kept to the 24 bits a float holds exactly.
// Integer maths: exact for any frame count, and identical on CPU and GPU.
inline float goldenPhase(uint32_t start, uint32_t frame) {
  return float((start + frame * kGoldenStep) >> 8) * (1.0f / 16777216.0f);
}

// The per-pixel stratification phase u: a hash of (pixel, seed) stepped by the golden ratio each frame,
// so neighbours sample different wavelengths and history accumulation sees each pixel's phase walk the
// stratum evenly. That is fract(hash01(pixel, seed) + frame * 0.618...). Stratum centres (0.5) with
// jitter off.
inline float spectralPhase(glm::uvec2 pixel, uint32_t frame, uint32_t seed, bool jitter) {
  return jitter ? goldenPhase(maths::pcg3d({pixel.x, pixel.y, seed}).x, frame) : 0.5f;
}

// Approx mode's single wavelength for the whole frame (the shared inside path), walking [380, 700) by the
// golden ratio from a seed-dependent start. Its hash key is a pixel no image has, so it does not echo
// pixel (0, 0)'s phase. 550 nm with jitter off.
inline float heroLambda(uint32_t frame, uint32_t seed, bool jitter) {
  if (!jitter) return kHeroLambdaFixed;
  return kLambdaMin + (kLambdaMax - kLambdaMin) * goldenPhase(maths::pcg3d({~0u, ~0u, seed}).x, frame);
}

// --- Tone mapping -----------------------------------------------------------------------------------

// Khronos PBR Neutral (2024) for the physical mode, instead of clipping at 1 as the original does. A colour
// whose brightest channel stays below about 0.8 only loses one offset shared by all channels (0.04, less in the
// quadratic toe: 0 -> 0, mid-grey 0.18 -> 0.14), so refracted background keeps its hue and contrast; above,
// the peak is compressed toward 1 and the colour desaturated toward white, the way film burns out.
// Chosen over maths::acesNarkowicz, whose curve is art-directed for KIFS and shifts hues.
inline glm::vec3 filmic(glm::vec3 color) {
  constexpr float kStart = 0.8f - 0.04f;  // where compression begins, after the toe's 0.04 offset
  constexpr float kDesaturation = 0.15f;
  const float x = glm::min(color.x, glm::min(color.y, color.z));
  const float offset = x < 0.08f ? x - 6.25f * x * x : 0.04f;
  color -= offset;
  const float peak = glm::max(color.x, glm::max(color.y, color.z));
  if (peak < kStart) return color;
  const float d = 1.0f - kStart;
  const float newPeak = 1.0f - d * d / (peak + d - kStart);
  color *= newPeak / peak;
  const float g = 1.0f - 1.0f / (kDesaturation * (peak - newPeak) + 1.0f);
  return glm::mix(color, glm::vec3(newPeak), g);
}

}  // namespace vitrine::glass
