// Scenes by name: the built-in scenes' generated factories, then those of pieces added at run time.
#include "scenes/scene.h"

#include <map>

namespace vitrine {
namespace {

std::map<std::string, SceneFactory, std::less<>>& runtimeFactories() {
  static std::map<std::string, SceneFactory, std::less<>> factories;
  return factories;
}

}  // namespace

SceneFactory sceneFactory(const SceneInfo& info) {
  for (const SceneFactoryEntry& entry : sceneFactories())
    if (entry.name == info.name) return entry.create;
  if (const auto it = runtimeFactories().find(info.name); it != runtimeFactories().end()) return it->second;
  return nullptr;
}

void addSceneFactory(std::string name, SceneFactory create) { runtimeFactories()[std::move(name)] = std::move(create); }

}  // namespace vitrine
