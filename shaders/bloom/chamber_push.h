// The chamber pass's push block, one declaration for both sides: bloom_scene.cpp fills it,
// chamber.comp reads it (shaders/common/interop.h says how). The colour comes first: a vec3 is
// 16-byte aligned in GLSL, so the two floats after it pack with no padding on either side.
#ifndef BLOOM_CHAMBER_PUSH_H
#define BLOOM_CHAMBER_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct BloomChamberPush {
  vec3 glowColour;  // the crystal's colour now, linear
  float shadow;     // how dark the floor shadow is at its centre (deepens as the crystal fills)
  float glow;       // warm light the crystal throws on the floor (0..1)
};
VITRINE_SHARED_END

#endif
