#pragma once
#include "scenes/scene.h"

namespace vitrine::glass {
extern const SceneInfo kSceneInfo;
}
