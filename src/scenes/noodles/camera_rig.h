#pragma once
// Which camera is flying: the lissajous flight, or - while the left button drags, and gliding back
// over a second and a half after release - an orbit that starts wherever the flight was.
// Reduced motion freezes the flight at its t = 0 pose and leaves a dragged camera where it was put.
// pin() holds a given orbit until unpinned or dragged: reproducible views for tests and screenshots.
#include "scenes/noodles/camera.h"
#include "scenes/scene.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vitrine::noodles {

class CameraRig {
 public:
  static constexpr float kReturnSeconds = 1.5f;

  void pin(const Orbit& orbit) {
    orbit_ = orbit;
    orbitWeight_ = 1.0f;
    pinned_ = true;
  }
  void unpin() { pinned_ = false; }

  // `nest` is roughly how far the strands reach from `centre`.
  void update(const FrameInput& input, float nest, glm::vec3 centre) {
    centre_ = centre;
    flight_ = lissajousPose(input.reducedMotion ? 0.0 : input.time, nest);
    flight_.eye += centre;
    flight_.target += centre;
    const CursorInput& cursor = input.cursor;
    if (cursor.dragging) {
      if (!dragging_) orbit_ = orbitThrough(pose(), centre_);  // pick up from wherever the camera is now
      constexpr float pi = std::numbers::pi_v<float>;
      orbit_.azimuth -= cursor.dragDelta.x * pi;  // a drag across the whole view: half a turn
      orbit_.elevation = std::clamp(orbit_.elevation + cursor.dragDelta.y * pi * 0.5f, -kMaxElevation, kMaxElevation);
      orbitWeight_ = 1.0f;
      pinned_ = false;
    } else if (!input.reducedMotion && !pinned_) {
      orbitWeight_ = std::max(orbitWeight_ - input.dt / kReturnSeconds, 0.0f);
    }
    dragging_ = cursor.dragging;
    if (cursor.wheel != 0.0f) zoom_ = std::clamp(zoom_ * std::pow(0.9f, cursor.wheel), 0.2f, 5.0f);
  }

  CameraPose pose() const {
    const float w = orbitWeight_ * orbitWeight_ * (3.0f - 2.0f * orbitWeight_);  // smoothstep: no jolt either end
    const CameraPose orbit = orbitPose(orbit_, centre_);
    const glm::vec3 target = glm::mix(flight_.target, orbit.target, w);
    const glm::vec3 eye = glm::mix(flight_.eye, orbit.eye, w);
    return {target + (eye - target) * zoom_, target};
  }

 private:
  CameraPose flight_{{1.0f, 0.0f, 0.0f}, glm::vec3(0.0f)};
  Orbit orbit_;
  glm::vec3 centre_{0.0f};
  float orbitWeight_ = 0.0f;
  float zoom_ = 1.0f;
  bool dragging_ = false;
  bool pinned_ = false;
};

}  // namespace vitrine::noodles
