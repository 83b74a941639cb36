#include "lights/light_guard.h"

#include <algorithm>

namespace vitrine::lights {

std::vector<glm::vec3> LightGuard::limit(const std::vector<glm::vec3>& wanted, float dt, bool dark) {
  namespace flash = host::flash;
  if (lights_.size() != wanted.size()) lights_.assign(wanted.size(), Light{});  // a new patch starts afresh
  std::vector<glm::vec3> shown(wanted.size());
  for (size_t i = 0; i < wanted.size(); ++i) {
    Light& light = lights_[i];
    const glm::vec3 next = dark ? glm::vec3(0.0f) : wanted[i];
    flash::Ages general = light.general, red = light.red;
    const int g = flash::generalTransition(light.shown, next) != 0 ? 1 : 0;
    const int r = flash::redTransition(light.shown, next) != 0 ? 1 : 0;
    const bool allowed = flash::admit(general, dt, g) && flash::admit(red, dt, r);
    if (allowed || dark) {
      if (!allowed) {  // blackout: shown anyway, and remembered as the transitions it makes
        general = light.general, red = light.red;
        flash::admit(general, dt, 0), flash::admit(red, dt, 0);
        for (int n = 0; n < g; ++n) *std::max_element(general.begin(), general.end()) = 0.0f;
        for (int n = 0; n < r; ++n) *std::max_element(red.begin(), red.end()) = 0.0f;
      }
      light.general = general, light.red = red, light.shown = next;
    } else {
      flash::admit(light.general, dt, 0), flash::admit(light.red, dt, 0);  // the window moves on
      ++held_;
    }
    shown[i] = light.shown;
  }
  return shown;
}

}  // namespace vitrine::lights
