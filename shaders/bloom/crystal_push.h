// The crystal pass's push block, one declaration for both sides: bloom_scene.cpp fills it,
// crystal.vert and crystal.frag read it (shaders/common/interop.h says how).
#ifndef BLOOM_CRYSTAL_PUSH_H
#define BLOOM_CRYSTAL_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct BloomCrystalPush {
  mat4 viewProjection;
  vec3 eye;
  float time;        // seconds: the climax's spectral shimmer moves with it
  vec3 thresholds;   // amber's, rose's and crimson's concentrations (bloom_math.h: vapourColour)
  uint seed;
  uint frame;        // 0 under reduced motion: the jitter holds still
  uint samples;      // volume samples along the longest chord (56); shorter chords take fewer
  float shimmer;     // climax: 0..1 (0 under reduced motion)
  uint clearGlass;   // 1: no voxel is past kCoverFrom, so every sample would be the glass's density
};
VITRINE_SHARED_END

#endif
