#pragma once
// Everything the calibration card's panel, --set and the settings file can change, declared once
// (params/schema.h). Apart from the scene so that what reads values needs no GPU code.
#include "params/schema.h"
#include "scenes/catalogue.h"

namespace vitrine::calibrate {

enum class StrobeColour { White, Red };

struct Settings {
  bool strobe = false;  // the flash guard's test: off unless asked for
  float strobeHz = 10.0f;
  StrobeColour strobeColour = StrobeColour::White;
};

const params::Schema& schema();
// What the scene is by name: its title, key, help line and actions, with the schema above.
extern const SceneInfo kSceneInfo;

}  // namespace vitrine::calibrate
