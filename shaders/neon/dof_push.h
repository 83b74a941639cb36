// The depth of field's push block, one declaration for both sides: src/scenes/neon/look_passes.cpp
// fills it, dof.comp reads it.
#ifndef NEON_DOF_PUSH_H
#define NEON_DOF_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct NeonDofPush {
  vec2 frameSize;       // pixels, of colour, depth and target
  float near;           // the projection's near distance: linear depth = near / depth
  float focalDistance;  // linear depth in sharp focus, world units
  float aperture;       // circle of confusion at infinity, pixels (its radius)
  float maxRadius;      // clamp on the circle of confusion and the spiral's radius, pixels
  uint taps;            // spiral taps, 24..32 is plenty; 0 copies the colour through
  float spin;           // radians the spiral is turned by; 0 keeps the picture still
};
VITRINE_SHARED_END

#endif
