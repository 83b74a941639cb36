#include "lights/signals.h"

#include <algorithm>
#include <cmath>

namespace vitrine::lights {

void Signals::set(std::string_view name, std::vector<glm::vec3> colours) {
  if (colours.size() > kMaxSignalColours) colours.resize(kMaxSignalColours);
  for (glm::vec3& c : colours)
    for (int i = 0; i < 3; ++i) c[i] = std::isfinite(c[i]) ? std::clamp(c[i], 0.0f, 1.0f) : 0.0f;
  colours_.insert_or_assign(std::string(name), std::move(colours));
}

const std::vector<glm::vec3>* Signals::find(std::string_view name) const {
  const auto it = colours_.find(name);
  return it == colours_.end() ? nullptr : &it->second;
}

}  // namespace vitrine::lights
