#pragma once
#include "scenes/scene.h"

namespace vitrine::calibrate {
extern const SceneInfo kSceneInfo;
}
