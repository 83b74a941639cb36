#pragma once
// The camera in plain maths: a lissajous flight in and out of the nest, an orbit for dragging, and
// the infinite reverse-Z projection (right-handed, z up, Vulkan clip space).
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace vitrine::noodles {

struct CameraPose {
  glm::vec3 eye;
  glm::vec3 target;
};

inline constexpr float kFieldOfViewY = 0.7f;  // radians (40 degrees)
inline constexpr float kNearPlane = 0.25f;    // tubes closer than this vanish as the camera flies through them
inline constexpr float kMaxElevation = 1.45f; // keeps the view off the up axis, where look-at degenerates

// Depth = near / distance: 1 at the near plane, falling towards 0 at infinity, so float depth keeps
// its precision far away (reverse-Z) and nothing is ever clipped by a far plane. Clip y is negated
// because Vulkan's framebuffer y points down.
inline glm::mat4 reverseZPerspective(float fovY, float aspect, float nearPlane) {
  const float focal = 1.0f / std::tan(fovY * 0.5f);
  glm::mat4 m(0.0f);
  m[0][0] = focal / aspect;
  m[1][1] = -focal;
  m[2][3] = -1.0f;      // w = -z_view: distance in front of a camera looking down -z
  m[3][2] = nearPlane;  // z = near
  return m;
}

// Right-handed view matrix looking from eye at target with z up.
inline glm::mat4 lookAtZUp(glm::vec3 eye, glm::vec3 target) {
  const glm::vec3 forward = glm::normalize(target - eye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 0.0f, 1.0f)));
  const glm::vec3 up = glm::cross(right, forward);
  glm::mat4 m(1.0f);
  for (int i = 0; i < 3; ++i) {
    m[i][0] = right[i];
    m[i][1] = up[i];
    m[i][2] = -forward[i];
  }
  m[3][0] = -glm::dot(right, eye);
  m[3][1] = -glm::dot(up, eye);
  m[3][2] = glm::dot(forward, eye);
  return m;
}

inline glm::vec3 fromSpherical(float azimuth, float elevation, float distance) {
  return distance * glm::vec3(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                              std::sin(elevation));
}

// A lissajous figure in azimuth, elevation and distance around the nest (radius `nest`, centred on
// the origin; the caller moves it): the
// distance swings from inside the nest (0.4 nest) to well outside it (2.8 nest) on a period that
// beats against the turning and bobbing, so the flight never quite repeats. The target wanders a
// little inside the nest, never near the eye.
inline CameraPose lissajousPose(double time, float nest) {
  const float t = float(std::fmod(time, 20000.0));  // all rates below are < 1/s: float keeps ms precision
  const float azimuth = 0.6f * std::sin(0.09f * t) + 0.11f * t;
  const float elevation = 0.45f * std::sin(0.23f * t + 0.7f);
  const float distance = nest * (1.6f - 1.2f * std::cos(0.17f * t + 2.4f));
  const glm::vec3 target =
      nest * 0.1f * glm::vec3(std::sin(0.31f * t), std::sin(0.37f * t + 1.0f), 0.5f * std::sin(0.29f * t));
  return {fromSpherical(azimuth, elevation, distance), target};
}

struct Orbit {
  float azimuth = 0.0f;
  float elevation = 0.3f;
  float distance = 1.0f;
};

inline CameraPose orbitPose(const Orbit& orbit, glm::vec3 centre) {
  return {centre + fromSpherical(orbit.azimuth, orbit.elevation, orbit.distance), centre};
}

// The orbit about `centre` that starts where `pose` is.
inline Orbit orbitThrough(const CameraPose& pose, glm::vec3 centre) {
  const glm::vec3 e = pose.eye - centre;
  const float distance = std::max(glm::length(e), 1e-3f);
  return {std::atan2(e.y, e.x), std::clamp(std::asin(std::clamp(e.z / distance, -1.0f, 1.0f)), -kMaxElevation,
                                           kMaxElevation),
          distance};
}

}  // namespace vitrine::noodles
