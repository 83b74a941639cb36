// The calibration card's push block, one declaration for both sides: calibrate/calibrate_scene.cpp
// fills it, card.comp reads it.
#ifndef CALIBRATE_CARD_PUSH_H
#define CALIBRATE_CARD_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct CalibrateCardPush {
  vec4 strobeColour;  // linear rgb of the strobe's lit half; a: unused
  uint strobeLit;     // non-zero: the strobe patch is lit this frame
  uint strobeOn;      // non-zero: the strobe patch is shown at all
};
VITRINE_SHARED_END

#endif
