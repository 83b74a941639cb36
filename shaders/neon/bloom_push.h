// The bloom chain's push blocks, one declaration for both sides: src/scenes/neon/look_passes.cpp fills
// them, bloom_down.comp and bloom_up.comp read them (src/scenes/neon/look.h documents the chain).
#ifndef NEON_BLOOM_PUSH_H
#define NEON_BLOOM_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct NeonBloomDownPush {
  float sourceLod;  // the mip of `source` holding level L - 1: 0 for a one-level view
  float threshold;  // brightness (max channel) where the bloom starts; used when `prefilter` is set
  float knee;       // half-width of the soft transition around the threshold (0: a hard cut)
  uint prefilter;   // 1 on the first step only
};

struct NeonBloomUpPush {
  float smallerLod;  // the mip of `smaller` holding level L + 1: 0 for a one-level view
  float currentLod;  // the mip of `current` holding level L: 0 for a one-level view
  float radius;      // tent tap spacing in target texels: 1 is smooth, more spreads the glow wider
  float scale;       // weight of the wider levels against this one: 1 sums them evenly, < 1 tightens the glow
};
VITRINE_SHARED_END

#endif
