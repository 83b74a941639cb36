// The flash guard's blocks, one declaration for both sides: host/flash_guard.cpp fills the push
// blocks and owns the buffer, flash_measure.comp, flash_decide.comp and flash_present.comp read them.
#ifndef HOST_FLASH_GUARD_BLOCKS_H
#define HOST_FLASH_GUARD_BLOCKS_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
// The guard's state on the GPU, kept by the host between frames (never read back by it).
struct HostFlashGuardState {
  // This frame's pixels in transition against what was shown last, added up by the measuring pass
  // and cleared by the deciding pass once read.
  uint generalRising;
  uint generalFalling;
  uint redRising;
  uint redFalling;
  // The ages in seconds of the transitions shown lately, of each kind (host/flash_guard_math.h's Ages).
  float generalAges[8];
  float redAges[8];
  // The decision for this frame: non-zero, its transitions of that kind are shown.
  uint showGeneral;
  uint showRed;
  uint limitedFrames;  // frames whose change was held back, since the guard began
  uint pad;
};

struct HostFlashMeasurePush {
  float fade;  // the incoming scene's weight, 0..1 (present_push.h's)
};

struct HostFlashDecidePush {
  float dt;    // seconds since the last frame the guard saw
  uint area;   // pixels that must change together for a frame to be a transition
  uint reset;  // non-zero: no history (a new output size, time went back): forget every transition
};

struct HostFlashPresentPush {
  float fade;         // as present_push.h's
  uint historyValid;  // zero: the held image has no earlier frame, show this one as it is
};
VITRINE_SHARED_END

#endif
