#pragma once
// The neon scene's look: the curves its compute passes use, in plain C++ (the reference the unit tests
// check; shaders/neon/look.glsl mirrors them line for line), and the passes' push-constant structs with
// their GLSL offsets pinned. The passes, all compute, 8x8 groups, one invocation a pixel of the target:
//
//   bloom_down.comp  0 sampler2D source (level L-1)  1 rgba16f image target (level L)       BloomDownPush
//   bloom_up.comp    0 sampler2D smaller (level L+1) 1 sampler2D current (down chain, L)
//                    2 rgba16f image target (up chain, level L)                             BloomUpPush
//   dof.comp         0 sampler2D colour  1 sampler2D depth (D32)  2 rgba16f image target   DofPush
//                    (both read with texelFetch: any sampler will do)
//   composite.comp   0 sampler2D scene   1 sampler2D bloom (up chain, level 1)
//                    2 rgba16f image target (tone-mapped, linear light)                     CompositePush
//
// Samplers are linear, clamp to edge. The bloom chain: level 0 is the full-size HDR image to bloom,
// level L is max(1, size >> L) for L = 1..N. Two rgba16f images, SAMPLED | STORAGE, a view per mip:
// `down` holds levels 1..N (mip L-1 = level L), `up` levels 1..N-1 (mip L-1 = level L). Then
//   1. bloom_down: source = the HDR image,          target = down mip 0,   prefilter = 1
//   2. bloom_down: source = down mip L-2,           target = down mip L-1, for L = 2..N
//   3. bloom_up:   smaller = down mip N-1 (level N), current = down mip N-2, target = up mip N-2
//   4. bloom_up:   smaller = up mip L,               current = down mip L-1, target = up mip L-1, for L = N-2..1
//   5. composite:  bloom = up mip 0 (level 1; for N = 1, down mip 0)
// with a compute-write -> compute-read barrier after each dispatch. No dispatch samples the mip it
// writes. With one-mip views every *Lod field is 0; binding a whole chain as one view instead needs the
// stock sampler with mipmaps (the others clamp to mip 0) and the mip in the *Lod field.
#include <glm/common.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace vitrine::neon {

inline constexpr float kGoldenAngle = 2.39996323f;  // pi * (3 - sqrt(5)) radians

// The seed's colour mask: darkens by how far `blend` is from white; white leaves `base` alone.
inline glm::vec3 linearBurn(glm::vec3 base, glm::vec3 blend) { return glm::max(base + blend - 1.0f, 0.0f); }

// Signed circle of confusion in pixels from a reverse-Z infinite-far depth value (linear depth = near /
// depth): aperture * (1 - focal / linearDepth), clamped to +-maxRadius. Negative in front of the focal
// plane, positive behind, zero on it; the sky (depth 0) gets `aperture`, the limit at infinity.
inline float circleOfConfusion(float depth, float near, float focal, float aperture, float maxRadius) {
  return glm::clamp(aperture * (1.0f - focal * depth / near), -maxRadius, maxRadius);
}

// Darkening towards the corners: 1 within 0.3 of the centre, easing to 1 - strength at the corners.
// `r` is the distance from the frame's centre over the distance to a corner.
inline float vignette(float r, float strength) { return 1.0f - strength * glm::smoothstep(0.3f, 1.0f, r); }

// The ground's reflection looks up the pixel mirrored about the horizon line (pixels, y down).
inline float mirrorY(float y, float horizonY) { return 2.0f * horizonY - y; }

// Tap i of n on a golden-angle spiral filling the unit disc evenly.
inline glm::vec2 spiralTap(uint32_t i, uint32_t n) {
  const float r = std::sqrt((float(i) + 0.5f) / float(n));
  const float a = float(i) * kGoldenAngle;
  return r * glm::vec2(std::cos(a), std::sin(a));
}

// The pixel row a world point projects to, for the composite's horizonY. Pass the facade's foot
// (0, 0, 0) rather than the true horizon: mirroring about it is exact for the front plane (every point
// of it lies at one depth) with a level camera, and close for a gently pitched one. Expects a
// projection with Vulkan's y-down clip space (the repo's reverseZPerspective negates y).
inline float projectedRow(const glm::mat4& viewProjection, glm::vec3 world, float frameHeight) {
  const glm::vec4 clip = viewProjection * glm::vec4(world, 1.0f);
  return (clip.y / clip.w * 0.5f + 0.5f) * frameHeight;
}

// Bloom levels for a frame `height` pixels tall: halve until the smallest level is about 16 rows tall
// (a blur as wide as the frame gains nothing from going smaller), at least 1, at most 8.
inline int bloomLevels(uint32_t height) {
  int levels = 1;
  while (levels < 8 && (height >> (levels + 1)) >= 16u) ++levels;
  return levels;
}

// The bloom's soft threshold on the tubes' light (which holds nothing but tubes): low, so a dim or
// dying tube still glows a little, while the knee keeps the faintest rims out.
inline constexpr float kBloomThreshold = 0.3f;
inline constexpr float kBloomKnee = 0.25f;

struct BloomDownPush {     // bloom_down.comp
  float sourceLod = 0.0f;  // the mip of `source` holding level L - 1
  float threshold = 1.0f;  // max-channel brightness where the bloom starts (prefilter only)
  float knee = 0.5f;       // half-width of the soft transition around it (0: a hard cut)
  uint32_t prefilter = 0;  // 1 on the first step only
};
static_assert(offsetof(BloomDownPush, threshold) == 4 && offsetof(BloomDownPush, knee) == 8 &&
              offsetof(BloomDownPush, prefilter) == 12 && sizeof(BloomDownPush) == 16);

struct BloomUpPush {        // bloom_up.comp
  float smallerLod = 0.0f;  // the mip of `smaller` holding level L + 1
  float currentLod = 0.0f;  // the mip of `current` holding level L
  float radius = 1.0f;      // tent tap spacing in target texels
  float scale = 1.0f;       // weight of the wider levels against this one
};
static_assert(offsetof(BloomUpPush, currentLod) == 4 && offsetof(BloomUpPush, radius) == 8 &&
              offsetof(BloomUpPush, scale) == 12 && sizeof(BloomUpPush) == 16);

struct DofPush {                // dof.comp
  glm::vec2 frameSize{0.0f};    // pixels, of colour, depth and target
  float near = 0.1f;            // linear depth = near / depth
  float focalDistance = 30.0f;  // world units
  float aperture = 6.0f;        // circle of confusion at infinity, pixels
  float maxRadius = 12.0f;      // pixels: clamps the circle and sizes the spiral
  uint32_t taps = 32;           // 0 copies the colour through
  float spin = 0.0f;            // radians; 0 keeps a still camera's picture still
};
static_assert(offsetof(DofPush, near) == 8 && offsetof(DofPush, focalDistance) == 12 &&
              offsetof(DofPush, aperture) == 16 && offsetof(DofPush, maxRadius) == 20 &&
              offsetof(DofPush, taps) == 24 && offsetof(DofPush, spin) == 28 && sizeof(DofPush) == 32);

// The composite's effect switches. The lead's `stage` picks the input image and these:
//   0 base, 1 tubes: none   2 bloom: kBloom   3 dof: kBloom (scene = the DOF output)
//   4 tint: kBloom | kTint  5 final: kCompositeAll
// The tone map is always on.
enum CompositeFlag : uint32_t {
  kCompositeBloom = 1u << 0,
  kCompositeTint = 1u << 1,
  kCompositeVignette = 1u << 2,
  kCompositeGrain = 1u << 3,
  kCompositeAberration = 1u << 4,
  kCompositeMirror = 1u << 5,
  kCompositeAll = (1u << 6) - 1u,
};

struct CompositePush {                        // composite.comp
  glm::vec3 tintColour0{1.0f, 0.78f, 0.86f};  // linear; light colours tint gently (see composite.comp)
  float tintStrength = 0.5f;                  // mix from the plain image to the burned one
  glm::vec3 tintColour1{0.70f, 0.86f, 1.0f};
  float time = 0.0f;               // seconds: the tint's noise and the ripples drift with it
  float bloomStrength = 0.1f;      // the up chain sums every level, hence small
  float bloomLod = 0.0f;           // the mip of `bloom` holding level 1
  float vignette = 0.35f;          // corner darkening, 0..1
  float grain = 0.03f;             // amplitude in a square-root encoding
  float aberration = 0.004f;       // red/blue shift per unit distance from the centre, uv
  float horizonY = 0.0f;           // the mirror line, pixels from the top (projectedRow of the facade's foot)
  float mirrorStrength = 0.35f;    // the reflection's brightness at the line
  float mirrorDistortion = 40.0f;  // ripple offset, pixels, a frame height below the line
  float mirrorFade = 300.0f;       // pixels below the line where the reflection has faded out
  uint32_t frame = 0;              // grain seed
  uint32_t flags = kCompositeAll;
};
static_assert(offsetof(CompositePush, tintStrength) == 12 && offsetof(CompositePush, tintColour1) == 16 &&
              offsetof(CompositePush, time) == 28 && offsetof(CompositePush, bloomStrength) == 32 &&
              offsetof(CompositePush, bloomLod) == 36 && offsetof(CompositePush, vignette) == 40 &&
              offsetof(CompositePush, grain) == 44 && offsetof(CompositePush, aberration) == 48 &&
              offsetof(CompositePush, horizonY) == 52 && offsetof(CompositePush, mirrorStrength) == 56 &&
              offsetof(CompositePush, mirrorDistortion) == 60 && offsetof(CompositePush, mirrorFade) == 64 &&
              offsetof(CompositePush, frame) == 68 && offsetof(CompositePush, flags) == 72 &&
              sizeof(CompositePush) == 76);

}  // namespace vitrine::neon
