#pragma once
#include "scenes/scene.h"

namespace vitrine::neon {
extern const SceneInfo kSceneInfo;
}
