#pragma once
#include "scenes/scene.h"

namespace vitrine::kifs {
extern const SceneInfo kSceneInfo;
}
