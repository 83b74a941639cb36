#pragma once
// The flow baked into a volume once a frame, which the integrate pass samples trilinearly instead of
// evaluating the noise. A step of the exact field costs three gradient noises (24 hashed lattice
// corners, ~1,400 instructions); a trilinear sample costs eight independent texel fetches. With
// 10^8 segments the noise is the whole of the integrate pass's time, and the bake (one exact
// evaluation a texel) is a small fraction of it, so large nests bake and small ones stay exact.
//
// Accuracy: at kBakeTexelsPerNoiseUnit = 8 the baked curl field is within ~5 % (rms) of the exact
// one (4.7 % measured), so a streamline follows the same swirls but parts from its exact twin by
// about a twentieth of its length over 60 steps (5.6 %; both in tests/unit/noodles_test.cpp); each
// strand is still a streamline of a field within 5 % of the divergence-free one, and the nest keeps
// its look. Points outside the volume (the few
// strands that travel further than the planned reach) take the exact field.
// Mirrored by shaders/noodles/integrate_baked.comp (sampling) and bake.comp (the texels).
#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

namespace vitrine::noodles {

enum class FieldSource : uint32_t { Auto, Exact, Baked };

inline constexpr float kBakeTexelsPerNoiseUnit = 8.0f;
// Auto bakes when the exact field would be evaluated this many times per texel or more (the bake then
// costs an eighth of the exact pass or less, and a baked step about a quarter of an exact one), and
// only past kBakeFromEvaluations: below it the exact pass is too quick on a GPU to trade exactness for
// (docs/PERFORMANCE.md, noodles). So the scene's default
// nest (262,144 segments, RK4 included) and 10^6 stay exact; 10^7 and up bake.
inline constexpr double kBakePaysFrom = 8.0;
inline constexpr double kBakeFromEvaluations = 4e6;
// At most 2^24 texels (64 MiB at kBakedTexelBytes); a forced bake of a bigger box coarsens to fit.
inline constexpr uint64_t kBakeMostTexels = uint64_t(1) << 24;
inline constexpr uint32_t kBakeMostTexelsPerAxis = 1024;
// The volume holds each component as 10-bit unorm over [-kBakeRange, kBakeRange] (RGB10A2, 4 bytes a
// texel: half the fetch traffic of half floats; docs/PERFORMANCE.md, noodles, Decisions).
// Steps of 0.008, under 1 % of the flow's median speed (~1.1); the noise flows' components stay
// within 4 (their largest speed over 200,000 random points was 3.6).
// bake.comp writes the packed bits itself through a 32-bit unsigned view (bakedTexel), rounding to
// nearest: Vulkan lets a driver convert a float to unorm by either neighbouring step, and a driver
// that truncates biases the whole flow by half a step, which moves every strand of a baked nest.
inline constexpr float kBakeRange = 4.0f;
inline constexpr uint32_t kBakedTexelBytes = 4;  // RGB10A2

// A flow component's 10-bit level: the nearest, a half step rounding up.
inline uint32_t bakedLevel(float v) {
  const float unit = std::clamp(v / (2.0f * kBakeRange) + 0.5f, 0.0f, 1.0f);
  return uint32_t(std::floor(unit * 1023.0f + 0.5f));
}

// A texel as the volume's A2B10G10R10 words hold it: x in the low bits, alpha zero.
inline uint32_t bakedTexel(glm::vec3 v) { return bakedLevel(v.x) | bakedLevel(v.y) << 10 | bakedLevel(v.z) << 20; }

// A component as the sampler reads it back.
inline float unbakedComponent(uint32_t level) { return (float(level) / 1023.0f - 0.5f) * (2.0f * kBakeRange); }

// A flow component as the volume stores it, and back.
inline float bakedComponent(float v) { return unbakedComponent(bakedLevel(v)); }

struct FieldBake {
  glm::vec3 origin{0.0f};  // world position of texel (0, 0, 0)'s centre
  float spacing = 0.0f;    // world units between neighbouring texel centres
  glm::uvec3 texels{0};    // none: the exact field everywhere
  bool baked() const { return texels.x > 0; }
  uint64_t count() const { return uint64_t(texels.x) * texels.y * texels.z; }
  bool operator==(const FieldBake&) const = default;
};

// A bake of the box [lo, hi] (world units) for a field of this noise scale, or none when `source` is
// Exact, or Auto and the bake would not pay for `evaluations` exact field evaluations.
inline FieldBake planFieldBake(glm::vec3 lo, glm::vec3 hi, float noiseScale, double evaluations, FieldSource source) {
  if (source == FieldSource::Exact) return {};
  float spacing = 1.0f / (kBakeTexelsPerNoiseUnit * noiseScale);
  const glm::vec3 size = glm::max(hi - lo, glm::vec3(0.0f));
  const auto texelsAt = [&](float h) { return glm::uvec3(glm::ceil(size / h)) + 1u; };
  const auto countOf = [](glm::uvec3 n) { return double(n.x) * n.y * n.z; };
  glm::uvec3 texels = texelsAt(spacing);
  const bool fits = countOf(texels) <= double(kBakeMostTexels) && std::max({texels.x, texels.y, texels.z}) <= kBakeMostTexelsPerAxis;
  if (source == FieldSource::Auto &&
      (!fits || evaluations < kBakeFromEvaluations || evaluations < kBakePaysFrom * countOf(texels)))
    return {};
  while (countOf(texels) > double(kBakeMostTexels) || std::max({texels.x, texels.y, texels.z}) > kBakeMostTexelsPerAxis) {
    spacing *= 1.25f;  // a forced bake of a huge box: coarser, not bigger
    texels = texelsAt(spacing);
  }
  return {lo, spacing, texels};
}

// Where p falls in texel units (texel centres at whole numbers).
inline glm::vec3 bakeCoordinates(const FieldBake& bake, glm::vec3 p) { return (p - bake.origin) / bake.spacing; }

// Whether p lies where all eight texels of its trilinear sample exist.
inline bool insideBake(const FieldBake& bake, glm::vec3 p) {
  if (!bake.baked()) return false;
  const glm::vec3 u = bakeCoordinates(bake, p);
  return glm::all(glm::greaterThanEqual(u, glm::vec3(0.0f))) &&
         glm::all(glm::lessThanEqual(u, glm::vec3(bake.texels - 1u)));
}

// The trilinear sample at p (insideBake(p) must hold) of `texels`, x fastest, with float weights, as
// integrate_baked.comp takes it. Not a sampler's linear filter: its weights have the device's
// sub-texel precision (8 bits on NVIDIA, float on lavapipe, 4 allowed), and a strand integrated
// through a hundred samples then lands a pixel apart from one driver to the next.
inline glm::vec3 sampleBake(const FieldBake& bake, std::span<const glm::vec3> texels, glm::vec3 p) {
  const glm::vec3 u = bakeCoordinates(bake, p);
  const glm::uvec3 last = bake.texels - 1u;
  const glm::uvec3 base = glm::min(glm::uvec3(glm::floor(u)), glm::max(last, 1u) - 1u);
  const glm::vec3 f = u - glm::vec3(base);
  glm::vec3 sum{0.0f};
  for (uint32_t corner = 0; corner < 8; ++corner) {
    const glm::uvec3 o{corner & 1u, (corner >> 1) & 1u, corner >> 2};
    const glm::uvec3 at = glm::min(base + o, last);
    const glm::vec3 w = glm::mix(1.0f - f, f, glm::vec3(o));
    sum += w.x * w.y * w.z * texels[(size_t(at.z) * bake.texels.y + at.y) * bake.texels.x + at.x];
  }
  return sum;
}

}  // namespace vitrine::noodles
