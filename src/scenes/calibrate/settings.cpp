#include "scenes/calibrate/settings.h"

namespace vitrine::calibrate {

const params::Schema& schema() {
  static const params::Schema table = [] {
    auto s = params::Schema::forStruct<Settings>();
    s.add(params::boolParam<Settings>({"strobe", "strobe", "A patch of a quarter of the frame flashing, to check the "
                                       "flash guard. It flashes under reduced motion too: it is there to be held "
                                       "back. Harmful to watch without the guard.", "strobe", params::kTransient},
                                      &Settings::strobe));
    s.add(params::floatParam<Settings>({"strobe_hz", "flashes a second", "How often the strobe patch flashes.",
                                        "strobe"},
                                       &Settings::strobeHz, 1.0, 30.0));
    s.add(params::choiceParam<Settings>({"strobe_colour", "strobe colour", "White tests the general-flash limit, "
                                         "saturated red the red-flash limit.", "strobe"},
                                        &Settings::strobeColour, {"white", "red"}));
    return s;
  }();
  return table;
}

constinit const SceneInfo kSceneInfo{"calibrate", "Calibration card", 6, &schema,
    "A test card for the output: grid, circles, bars, ramp and corner markers; strobe=on tests the flash guard."};

}  // namespace vitrine::calibrate
