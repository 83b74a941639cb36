#pragma once
// Two divergence-free flows, in plain C++: curl noise (the curl of three noise potentials) and
// bitangent noise (the cross product of two noise gradients). Both are divergence free by
// construction: div curl = 0, and div(grad a x grad b) = 0. The noodles scene's strands follow either;
// neon's tube heads swim in the curl flow, without lift. Mirrored by shaders/common/flow_field.glsl.
#include "maths/noise.h"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace vitrine::maths {

enum class FieldKind : uint32_t { Curl, Bitangent };

// Where the second and third potentials sit in noise space: hundreds of cells from the first, where
// the one hash gives unrelated values, so one noise function serves as several (the write-up's
// offsets).
inline constexpr glm::vec3 kPotentialOffsetY{100.0f, 0.0f, 100.0f};
inline constexpr glm::vec3 kPotentialOffsetZ{-100.0f, 0.0f, -150.0f};

// Time moves the potentials through noise space, so the field morphs and the noodles writhe. The
// write-up slides them along +y forever; here they start along +y and bend round a circle this many
// noise cells across, so coordinates stay small enough for float (at t = 1e5 s a straight slide has
// lost four decimal digits) and the motion loops every 2 pi R noise units.
inline constexpr double kDriftRadius = 64.0;

struct FieldSettings {
  FieldKind kind = FieldKind::Curl;
  float noiseScale = 0.5f;                     // world -> noise coordinates
  glm::vec3 offsetY = kPotentialOffsetY;       // second potential, drift included
  glm::vec3 offsetZ = kPotentialOffsetZ;       // third potential, drift included
  float lift = 0.0f;  // a uniform upward flow added to the noise: still divergence free
  bool operator==(const FieldSettings&) const = default;
};

// The drift after `noiseTime` noise units of travel, computed in double on the CPU.
inline glm::vec3 driftOffset(double noiseTime) {
  const double angle = std::fmod(noiseTime / kDriftRadius, 2.0 * std::numbers::pi);
  return {float(kDriftRadius * (1.0 - std::cos(angle))), float(kDriftRadius * std::sin(angle)), 0.0f};
}

inline FieldSettings fieldAtTime(FieldKind kind, float noiseScale, float lift, double noiseTime) {
  const glm::vec3 drift = driftOffset(noiseTime);
  return {kind, noiseScale, kPotentialOffsetY + drift, kPotentialOffsetZ + drift, lift};
}

// curl(psi) with psi = (n(q), n(q + offsetY), n(q + offsetZ)); the first potential stays put, as in
// the write-up, so the field morphs rather than translating as a whole.
inline glm::vec3 curlNoise(glm::vec3 q, const FieldSettings& s) {
  const glm::vec3 gx = gradientNoise(q).gradient;
  const glm::vec3 gy = gradientNoise(q + s.offsetY).gradient;
  const glm::vec3 gz = gradientNoise(q + s.offsetZ).gradient;
  return {gz.y - gy.z, gx.z - gz.x, gy.x - gx.y};
}

// grad a x grad b: tangent to both families of level sets.
inline glm::vec3 bitangentNoise(glm::vec3 q, const FieldSettings& s) {
  return glm::cross(gradientNoise(q + s.offsetY).gradient, gradientNoise(q + s.offsetZ).gradient);
}

// The flow at world position p. Derivatives are taken in noise coordinates, as in the write-up, so
// noise_scale changes the size of the swirls but not the speed along them.
inline glm::vec3 flowVelocity(glm::vec3 p, const FieldSettings& s) {
  const glm::vec3 q = p * s.noiseScale;
  glm::vec3 v = s.kind == FieldKind::Curl ? curlNoise(q, s) : bitangentNoise(q, s);
  v.z += s.lift;
  return v;
}

}  // namespace vitrine::maths
