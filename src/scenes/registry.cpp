#include "scenes/bloom/bloom_scene.h"
#include "scenes/glass/glass_scene.h"
#include "scenes/kifs/kifs_scene.h"
#include "scenes/neon/neon_scene.h"
#include "scenes/noodles/noodles_scene.h"
#include "scenes/scene.h"

namespace vitrine {

std::span<const SceneInfo> sceneRegistry() {
  static const SceneInfo scenes[] = {
      bloom::kSceneInfo,
      glass::kSceneInfo,
      neon::kSceneInfo,
      kifs::kSceneInfo,
      noodles::kSceneInfo,
  };
  return scenes;
}

const SceneInfo* findScene(std::string_view name) {
  for (const auto& info : sceneRegistry())
    if (info.name == name) return &info;
  return nullptr;
}

}  // namespace vitrine
