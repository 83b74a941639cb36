#pragma once
#include "scenes/scene.h"

namespace vitrine::kifs {
// The scene, as the factory table (scenes/scene.h) makes it; what it is by name is settings.h's kSceneInfo.
std::unique_ptr<Scene> create(const SceneContext& context);
}
