#include "scenes/scene_events.h"

#include <fmt/format.h>

#include "core/error.h"

namespace vitrine {

const EventValue* SceneEvent::find(std::string_view key) const {
  for (const auto& [valueName, value] : values)
    if (valueName == key) return &value;
  return nullptr;
}

void checkSceneEvent(const SceneEvent& event) {
  if (event.name.empty()) throw Error("A scene event needs a name");
  for (auto it = event.values.begin(); it != event.values.end(); ++it) {
    const std::string& key = it->first;
    if (key == "t" || key == "scene" || key == "event")
      throw Error(fmt::format("Scene event '{}' has a value named '{}', which the log uses itself", event.name, key));
    for (auto earlier = event.values.begin(); earlier != it; ++earlier)
      if (earlier->first == key)
        throw Error(fmt::format("Scene event '{}' has two values named '{}'", event.name, key));
  }
}

}  // namespace vitrine
