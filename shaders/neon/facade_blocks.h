// The facade pass's blocks, one declaration for both sides: src/scenes/neon/facade.cpp lays out the
// boxes (uploaded once as a std430 array), neon_scene.cpp fills the push block, facade.comp reads both.
#ifndef NEON_FACADE_BLOCKS_H
#define NEON_FACADE_BLOCKS_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
// One axis-aligned box of the building, world space, metres.
struct NeonFacadeBox {
  vec3 centre;
  uint padding0;  // 0: in std430 a vec3 takes 16 bytes
  vec3 halfSize;  // every component > 0
  uint padding1;  // 0
};

struct NeonFacadePush {
  vec3 sky;                // linear rgb, where no box is hit
  float facadeBrightness;  // the lighting texture's scale: the tubes are the subject, the building their backdrop
};
VITRINE_SHARED_END

#endif
