#include "scenes/kifs/settings.h"

namespace vitrine::kifs {

const params::Schema& schema() {
  static const params::Schema table = [] {
    auto s = params::Schema::forStruct<Settings>();
    s.add(params::intParam<Settings>({"step", "stage", "How far the write-up's construction has got, 1 to 9 (9: the "
                                      "final piece)."}, &Settings::step, 1, kStepCount));
    addQualityParams<Settings>(s, "March budget and render scale", 8.0f);
    s.add(params::floatParam<Settings>({"fold", "fold", "Scales the fold's offsets: below 1 the fractal draws in, "
                                        "above 1 it opens (from stage 6).", "view"},
                                       &Settings::fold, 0.8, 1.3));
    s.add(params::floatParam<Settings>({"drag_x", "drag x", "Horizontal cursor drag turning the fractal.", "view",
                                        params::kTransient},
                                       &Settings::dragX, -100.0, 100.0));
    s.add(params::floatParam<Settings>({"drag_y", "drag y", "Vertical cursor drag turning the fractal.", "view",
                                        params::kTransient},
                                       &Settings::dragY, -100.0, 100.0));
    s.audioMapping("audio.bass=fold:1:1.14 attack=0.015 release=0.35");
    s.preset({"sphere", "The write-up's first step: one glowing sphere.", {{"step", "1"}}});
    s.preset({"final", "The finished piece at high quality.", {{"step", "9"}, {"tier", "high"}}});
    return s;
  }();
  return table;
}

constinit const SceneInfo kSceneInfo{"kifs", "Volumetric KIFS", 4, &schema,
    "Drag to nudge the fractal's orientation."};

}  // namespace vitrine::kifs
