#pragma once
// Tone and colour curves shared by scenes; mirrored by shaders/common/color.glsl.
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/vector_relational.hpp>
#include <glm/vec3.hpp>

namespace vitrine::maths {

// Narkowicz's rational fit of the ACES film curve, with the KIFS write-up's art-directed
// coefficients (a, b, c, d, e) = (2.38, -0.04, 2.35, 1.52, 0.14). The negative b dips below zero
// for x < 0.0168; clamping there makes the toe crush to black instead of inverting.
inline float acesNarkowicz(float x) {
  const float y = (x * (2.38f * x - 0.04f)) / (x * (2.35f * x + 1.52f) + 0.14f);
  return glm::max(y, 0.0f);
}
inline glm::vec3 acesNarkowicz(glm::vec3 c) { return {acesNarkowicz(c.x), acesNarkowicz(c.y), acesNarkowicz(c.z)}; }

inline glm::vec3 srgbToLinear(glm::vec3 c) {
  c = glm::clamp(c, 0.0f, 1.0f);
  return glm::mix(c / 12.92f, glm::pow((c + 0.055f) / 1.055f, glm::vec3(2.4f)),
                  glm::vec3(glm::greaterThan(c, glm::vec3(0.04045f))));
}

}  // namespace vitrine::maths
