#pragma once
// The flash guard's limits on the lights: the same WCAG 2.3.1 general and red flash thresholds the
// picture is held to (host/flash_guard_math.h), judged for each light on its own, since one lamp can
// fill a wall. A light's change that would make a general or red transition is shown only when its
// one-second window allows it; otherwise the light keeps what it showed. Going dark (blackout) is
// always shown, and counted.
#include "host/flash_guard_math.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace vitrine::lights {

class LightGuard {
 public:
  // The colours to send for `wanted` (one per light), `dt` seconds after the last call. `dark`: the
  // lights go dark whatever the window says (blackout).
  std::vector<glm::vec3> limit(const std::vector<glm::vec3>& wanted, float dt, bool dark = false);
  uint64_t held() const { return held_; }  // light changes held back so far

 private:
  struct Light {
    glm::vec3 shown{0.0f};
    host::flash::Ages general = host::flash::neverFlashed();
    host::flash::Ages red = host::flash::neverFlashed();
  };
  std::vector<Light> lights_;
  uint64_t held_ = 0;
};

}  // namespace vitrine::lights
