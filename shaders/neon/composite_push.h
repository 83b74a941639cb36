// The composite's push block and effect switches, one declaration for both sides:
// src/scenes/neon/look_passes.cpp fills it, composite.comp reads it.
#ifndef NEON_COMPOSITE_PUSH_H
#define NEON_COMPOSITE_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
// NeonCompositePush::flags, an effect each. The tone map is always on.
const uint NEON_COMPOSITE_BLOOM = 1u;
const uint NEON_COMPOSITE_TINT = 2u;
const uint NEON_COMPOSITE_VIGNETTE = 4u;
const uint NEON_COMPOSITE_GRAIN = 8u;
const uint NEON_COMPOSITE_ABERRATION = 16u;
const uint NEON_COMPOSITE_MIRROR = 32u;
const uint NEON_COMPOSITE_ALL = 63u;

struct NeonCompositePush {
  vec3 tintColour0;        // linear; the burn takes 1 - sqrt(colour) off sqrt(pixel): light colours tint gently
  float tintStrength;      // 0..1: mix from the plain image to the burned one
  vec3 tintColour1;        // the other tint colour, linear
  float time;              // seconds: drifts the tint's noise and the ripples
  float bloomStrength;     // the up chain sums every level, so this is small (about 0.02..0.1)
  float bloomLod;          // the mip of `bloom` to read: 0 for a one-level view
  float vignette;          // 0..1: how dark the corners get
  float grain;             // amplitude in a square-root encoding, about 0.02..0.05
  float aberration;        // red/blue shift per unit of distance from the centre, in uv (about 0.004)
  float horizonY;          // the mirror line, pixels from the top (projectedRow of the facade's foot)
  float mirrorStrength;    // 0..1: the reflection's brightness at the mirror line
  float mirrorDistortion;  // ripple offset in pixels a frame height below the mirror line
  float mirrorFade;        // pixels below the mirror line where the reflection has faded out
  uint frame;              // seeds the grain (hold it for still pictures)
  uint flags;              // NEON_COMPOSITE_* bits
};
VITRINE_SHARED_END

#endif
