#include "scenes/schemas.h"

#include "scenes/bloom/settings.h"
#include "scenes/glass/settings.h"
#include "scenes/kifs/settings.h"
#include "scenes/neon/settings.h"
#include "scenes/noodles/settings.h"

namespace vitrine {

std::span<const SceneSchema> sceneSchemas() {
  static const SceneSchema schemas[] = {
      {"bloom", &bloom::schema}, {"glass", &glass::schema}, {"neon", &neon::schema},
      {"kifs", &kifs::schema},   {"noodles", &noodles::schema},
  };
  return schemas;
}

}  // namespace vitrine
