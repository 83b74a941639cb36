#pragma once
// Everything the kifs panel, --set and the settings file can change, declared once (params/schema.h).
// Apart from the scene so that what reads values (the settings file, the fuzz targets) needs no GPU code.
#include "params/schema.h"
#include "scenes/catalogue.h"
#include "scenes/kifs/kifs_math.h"
#include "scenes/quality.h"

namespace vitrine::kifs {

struct Settings {
  int step = kStepCount;
  Tier tier = Tier::Auto;
  float targetMs = 8.0f;
  float fold = 1.0f;                 // the fold offsets' scale (live input plays it)
  float dragX = 0.0f, dragY = 0.0f;  // accumulated cursor drag, in normalised output units
};

const params::Schema& schema();
// What the scene is by name: its title, key, help line and actions, with the schema above.
extern const SceneInfo kSceneInfo;

}  // namespace vitrine::kifs
