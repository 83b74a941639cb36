#pragma once
// One step along a streamline, dp/ds = v(p): explicit Euler (the write-up's choice) or classic RK4,
// following either the raw field (strands move faster where the field is stronger, so segment
// lengths vary) or its direction (every segment is `step` long). Generic over the field so the unit
// tests can drive it with analytic flows; shaders/noodles/integrate.glsl mirrors it for the noise flow.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>

namespace vitrine::noodles {

enum class Integrator : uint32_t { Euler, Rk4 };
enum class TangentMode : uint32_t { Normalized, Raw };

// Below this squared speed the flow has no usable direction (a stagnation point).
inline constexpr float kStillSpeedSquared = 1e-20f;

// The unit direction of v, or `fallback` where v vanishes.
inline glm::vec3 directionOf(glm::vec3 v, glm::vec3 fallback) {
  const float speedSquared = glm::dot(v, v);
  return speedSquared > kStillSpeedSquared ? v / std::sqrt(speedSquared) : fallback;
}

// What a step follows: the field itself, or its direction.
inline glm::vec3 travel(glm::vec3 v, TangentMode mode) {
  if (mode == TangentMode::Raw) return v;
  const float speedSquared = glm::dot(v, v);
  return speedSquared > kStillSpeedSquared ? v / std::sqrt(speedSquared) : glm::vec3(0.0f);
}

// Advances p by one step of length parameter h. `k1` is travel(field(p)), which the caller has
// already evaluated for the frame at p, so Euler costs no further field evaluations and RK4 three.
template <typename Field>
glm::vec3 advance(glm::vec3 p, glm::vec3 k1, float h, Integrator integrator, TangentMode mode, const Field& field) {
  if (integrator == Integrator::Euler) return p + k1 * h;
  const glm::vec3 k2 = travel(field(p + k1 * (0.5f * h)), mode);
  const glm::vec3 k3 = travel(field(p + k2 * (0.5f * h)), mode);
  const glm::vec3 k4 = travel(field(p + k3 * h), mode);
  return p + (k1 + (k2 + k3) * 2.0f + k4) * (h / 6.0f);
}

}  // namespace vitrine::noodles
