#pragma once
#include "scenes/scene.h"

namespace vitrine::bloom {
extern const SceneInfo kSceneInfo;
}
