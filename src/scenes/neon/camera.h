#pragma once
// The neon scene's fixed camera: in front of the facade, a little above the ground, looking up at it;
// a reverse-Z projection with an infinitely far plane (depth = near / distance along the view).
#include "scenes/neon/facade.h"

#include <glm/common.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <optional>

namespace vitrine::neon {

inline constexpr glm::vec3 kEye = kCameraEye;     // facade.h frames the facade with these
inline constexpr glm::vec3 kLookAt = kCameraTarget;
inline constexpr float kFovY = kCameraFovY;
inline constexpr float kNear = 0.1f;
inline constexpr float kReleasePlaneZ = 4.0f;  // heads are released on this plane, in front of the facade

inline glm::mat4 viewMatrix() { return glm::lookAtRH(kEye, kLookAt, glm::vec3(0.0f, 1.0f, 0.0f)); }

// Reverse-Z, infinite far plane, Vulkan's y down: clip = (x f / aspect, -y f, near, -z).
inline glm::mat4 projectionMatrix(float aspect) {
  const float f = 1.0f / std::tan(0.5f * kFovY);
  glm::mat4 p(0.0f);
  p[0][0] = f / aspect;
  p[1][1] = -f;
  p[2][3] = -1.0f;
  p[3][2] = kNear;
  return p;
}

// Where a release from outside (remote control, a script) may put a head: the volume in front of the
// facade that the camera sees, so a stray "release 1e30 0 0" cannot send a chain where its maths breaks.
inline glm::vec3 clampToReleaseVolume(glm::vec3 at) {
  return glm::clamp(at, glm::vec3(-16.0f, 0.0f, kReleasePlaneZ - 8.0f), glm::vec3(16.0f, 20.0f, kReleasePlaneZ + 8.0f));
}

// The lowest a cursor's tube may be released, m above the ground: a tube's width above the floor, so
// none is born under it.
inline constexpr float kMinReleaseHeight = 0.5f;

// Where the cursor (normalised coordinates, origin top-left) releases and steers its tube: where its
// ray meets the release plane; a ray that meets the plane under kMinReleaseHeight (the lower fifth of
// the frame, where the ground shows) meets the level kMinReleaseHeight instead, nearer the camera, so
// the tube is drawn under the cursor and above the floor; no nearer than the release volume's front.
// Every point lies on the cursor's ray except in the last case, which keeps the height.
inline std::optional<glm::vec3> cursorOnReleasePlane(glm::vec2 normalized, float aspect) {
  const float f = std::tan(0.5f * kFovY);
  const glm::vec2 ndc = normalized * 2.0f - 1.0f;
  const glm::vec3 dir = glm::normalize(glm::transpose(glm::mat3(viewMatrix())) *
                                       glm::vec3(ndc.x * f * aspect, -ndc.y * f, -1.0f));
  if (dir.z > -1e-6f) return std::nullopt;  // the camera looks toward -z: such a ray never reaches the plane
  glm::vec3 at = kEye + dir * ((kReleasePlaneZ - kEye.z) / dir.z);
  if (at.y >= kMinReleaseHeight) return at;
  if (dir.y < 0.0f) at = kEye + dir * ((kMinReleaseHeight - kEye.y) / dir.y);
  constexpr float kFrontZ = kReleasePlaneZ + 8.0f;  // clampToReleaseVolume's front
  if (at.z > kFrontZ) at = kEye + dir * ((kFrontZ - kEye.z) / dir.z);
  at.y = std::max(at.y, kMinReleaseHeight);
  return at;
}

}  // namespace vitrine::neon
