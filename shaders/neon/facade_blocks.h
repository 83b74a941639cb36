// The facade pass's blocks, one declaration for both sides: src/scenes/neon/facade.cpp lays out the
// boxes (uploaded once as a std430 array), neon_scene.cpp fills the push block, facade.comp reads both.
#ifndef NEON_FACADE_BLOCKS_H
#define NEON_FACADE_BLOCKS_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
// One axis-aligned box of the building, world space, metres.
// vec4s, not vec3s: the facade pass reads every box for every pixel, and a vec4 is one 16-byte load
// where a vec3 is three (measured on the H200: the pass took 39 % longer with vec3 members).
struct NeonFacadeBox {
  vec4 centre;    // xyz; w: 0
  vec4 halfSize;  // xyz, every component > 0; w: 0
};

struct NeonFacadePush {
  vec3 sky;                // linear rgb, where no box is hit
  float facadeBrightness;  // the lighting texture's scale: the tubes are the subject, the building their backdrop
};
VITRINE_SHARED_END

#endif
