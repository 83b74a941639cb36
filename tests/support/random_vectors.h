#pragma once
// Reproducible random points and directions for the maths tests: hashed, so a failure names the
// index that fails and every run draws the same ones.
#include "maths/hash.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace vitrine::test {

// A point of the cube [-1, 1]^3, the i-th for this salt.
inline glm::vec3 randomSigned(uint32_t i, uint32_t salt) {
  return glm::vec3(maths::hash01({i, salt, 1u}), maths::hash01({i, salt, 2u}), maths::hash01({i, salt, 3u})) * 2.0f -
         1.0f;
}
// A unit direction, uniform over the sphere: rejection inside the unit ball.
inline glm::vec3 randomDirection(uint32_t i, uint32_t salt) {
  for (uint32_t k = 0;; ++k) {
    const glm::vec3 v = randomSigned(i, salt + 7919u * k);
    const float l = glm::length(v);
    if (l > 0.05f && l <= 1.0f) return v / l;
  }
}

}  // namespace vitrine::test
