#pragma once
#include "scenes/scene.h"

namespace vitrine::noodles {
extern const SceneInfo kSceneInfo;
}
