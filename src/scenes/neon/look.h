#pragma once
// The neon scene's look: the curves its compute passes use, in plain C++ (the reference the unit tests
// check; shaders/neon/look.glsl mirrors them line for line). The passes, all compute, one invocation a
// pixel of the target, their push blocks shared with C++ in shaders/neon/bloom_push.h, dof_push.h and
// composite_push.h:
//
//   bloom_down.comp  source (level L-1, sampled)  target (level L, rgba16f image)            NeonBloomDownPush
//   bloom_up.comp    smaller (level L+1, sampled)  current (down chain, level L, sampled)
//                    target (up chain, level L, rgba16f image)                               NeonBloomUpPush
//   dof.comp         colour (sampled)  depth (D32, sampled)  target (rgba16f image)          NeonDofPush
//                    (both read with texelFetch: any sampler will do)
//   composite.comp   scene (sampled)  bloom (up chain, level 1, sampled)
//                    target (rgba16f image: tone-mapped, linear light)                       NeonCompositePush
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
inline float spiralRadius(uint32_t i, uint32_t n) { return std::sqrt((float(i) + 0.5f) / float(n)); }
inline glm::vec2 spiralTap(uint32_t i, uint32_t n) {
  const float a = float(i) * kGoldenAngle;
  return spiralRadius(i, n) * glm::vec2(std::cos(a), std::sin(a));
}
// The shaders walk the spiral instead: tap i + 1's direction is tap i's turned by the golden angle (one
// complex product, where a cos and a sin a tap took llvmpipe half of its depth of field).
inline constexpr glm::vec2 kGoldenTurn{-0.737368822f, 0.675490379f};  // (cos, sin) of kGoldenAngle
inline glm::vec2 nextHeading(glm::vec2 heading) {
  return {heading.x * kGoldenTurn.x - heading.y * kGoldenTurn.y, heading.x * kGoldenTurn.y + heading.y * kGoldenTurn.x};
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

}  // namespace vitrine::neon
