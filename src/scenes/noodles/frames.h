#pragma once
// Orientation frames along a strand, which the tube's rings are built from, and the quaternion that
// stores one. Two ways to choose the normal:
//  - up-vector frames (the write-up's): normal = tangent x up. Each frame depends only on its own
//    tangent, so the normal spins around the strand wherever the tangent swings past the up axis,
//    twisting the tube like a wrung towel on near-vertical strands (and flipping on exactly vertical
//    ones);
//  - rotation-minimising frames by double reflection (Wang, Juettler, Zheng & Liu, "Computation of
//    rotation minimizing frames", ACM TOG 2008): each frame is the previous one carried to the next
//    point by two reflections, which approximates parallel transport to fourth order - no spin
//    about the tangent, whatever the direction.
// Mirrored by shaders/noodles/frames.glsl.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstdint>

namespace vitrine::noodles {

enum class FrameMethod : uint32_t { Up, RotationMinimizing };

// Right-handed and orthonormal: binormal = tangent x normal.
struct Frame {
  glm::vec3 normal;
  glm::vec3 binormal;
  glm::vec3 tangent;
};

inline constexpr glm::vec3 kWorldUp{0.0f, 0.0f, 1.0f};  // right-handed, z up
inline constexpr float kParallelSquared = 1e-12f;      // |t x up|^2 below this: t is vertical
inline constexpr float kNoTurnSquared = 1e-20f;        // a reflection about a shorter vector is skipped

inline Frame upVectorFrame(glm::vec3 tangent) {
  glm::vec3 side = glm::cross(tangent, kWorldUp);
  if (glm::dot(side, side) < kParallelSquared) side = glm::cross(tangent, glm::vec3(1.0f, 0.0f, 0.0f));
  const glm::vec3 normal = glm::normalize(side);
  return {normal, glm::cross(tangent, normal), tangent};
}

// Carries `from` (at fromPoint) to toPoint, where the curve's unit tangent is toTangent.
inline Frame transportFrame(const Frame& from, glm::vec3 fromPoint, glm::vec3 toPoint, glm::vec3 toTangent) {
  // First reflection, in the plane bisecting the chord: maps fromPoint to toPoint.
  const glm::vec3 chord = toPoint - fromPoint;
  const float chordSquared = glm::dot(chord, chord);
  glm::vec3 normal = from.normal;
  glm::vec3 tangent = from.tangent;
  if (chordSquared > kNoTurnSquared) {
    normal -= chord * (2.0f * glm::dot(chord, normal) / chordSquared);
    tangent -= chord * (2.0f * glm::dot(chord, tangent) / chordSquared);
  }
  // Second reflection: turns the reflected tangent onto the new one, taking the normal along.
  const glm::vec3 turn = toTangent - tangent;
  const float turnSquared = glm::dot(turn, turn);
  if (turnSquared > kNoTurnSquared) normal -= turn * (2.0f * glm::dot(turn, normal) / turnSquared);
  // Reflections keep lengths and angles exactly only in exact arithmetic; one Gram-Schmidt step stops
  // float drift from accumulating over thousands of segments.
  normal = glm::normalize(normal - toTangent * glm::dot(toTangent, normal));
  return {normal, glm::cross(toTangent, normal), toTangent};
}

// The unit quaternion (x, y, z, w = scalar) of the rotation taking the axes x, y, z to normal,
// binormal, tangent. Shepperd's method: divide by the largest of the four candidates, never by a
// small one.
inline glm::vec4 frameToQuaternion(const Frame& f) {
  const glm::vec3 &n = f.normal, &b = f.binormal, &t = f.tangent;  // the matrix's columns
  const float trace = n.x + b.y + t.z;
  if (trace > 0.0f) {
    const float s = std::sqrt(trace + 1.0f) * 2.0f;
    return {(b.z - t.y) / s, (t.x - n.z) / s, (n.y - b.x) / s, 0.25f * s};
  }
  if (n.x > b.y && n.x > t.z) {
    const float s = std::sqrt(1.0f + n.x - b.y - t.z) * 2.0f;
    return {0.25f * s, (b.x + n.y) / s, (t.x + n.z) / s, (b.z - t.y) / s};
  }
  if (b.y > t.z) {
    const float s = std::sqrt(1.0f + b.y - n.x - t.z) * 2.0f;
    return {(b.x + n.y) / s, 0.25f * s, (t.y + b.z) / s, (t.x - n.z) / s};
  }
  const float s = std::sqrt(1.0f + t.z - n.x - b.y) * 2.0f;
  return {(t.x + n.z) / s, (t.y + b.z) / s, 0.25f * s, (n.y - b.x) / s};
}

inline Frame quaternionToFrame(glm::vec4 q) {
  const float x = q.x, y = q.y, z = q.z, w = q.w;
  return {{1.0f - 2.0f * (y * y + z * z), 2.0f * (x * y + w * z), 2.0f * (x * z - w * y)},
          {2.0f * (x * y - w * z), 1.0f - 2.0f * (x * x + z * z), 2.0f * (y * z + w * x)},
          {2.0f * (x * z + w * y), 2.0f * (y * z - w * x), 1.0f - 2.0f * (x * x + y * y)}};
}

}  // namespace vitrine::noodles
