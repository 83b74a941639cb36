// The kifs march's push block, one declaration for both sides: kifs_scene.cpp fills it, kifs.comp
// reads it (shaders/common/interop.h says how one header serves GLSL and C++). The stage is not here:
// it is the pipeline's specialization constant (kifs.comp: KIFS_STAGE).
#ifndef KIFS_MARCH_PUSH_H
#define KIFS_MARCH_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct KifsMarchPush {
  vec2 angles;       // tumble + drag, radians on the xz and xy planes
  uint frame;        // decorrelates jitter and grain between frames
  uint seed;
  int maxSteps;      // march budget (quality tier)
  float grain;       // film grain amplitude (0 under reduced motion)
  uint jitterFrame;  // frame index for the ray-start jitter (frozen under reduced motion)
  float fold;        // the fold offsets' scale, 1: the write-up's
};
VITRINE_SHARED_END

#endif
