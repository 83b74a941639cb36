#pragma once
// Every scene's parameter declarations by name, without the scenes themselves: what reads values from
// outside (the settings file, --set, the fuzz targets in fuzz/) links this and the scenes' settings.cpp
// files, not their GPU code. The same scenes, in the same order, as sceneRegistry(): both tables are
// generated from cmake/Scenes.cmake (a unit test checks).
#include "params/schema.h"

#include <span>
#include <string_view>

namespace vitrine {

struct SceneSchema {
  std::string_view name;
  const params::Schema& (*schema)();
};

std::span<const SceneSchema> sceneSchemas();

}  // namespace vitrine
