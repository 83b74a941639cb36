// The chain pass's push block, one declaration for both sides: chainPush() in src/scenes/neon/chains.h
// fills it, shaders/neon/chains.comp reads it.
#ifndef NEON_CHAIN_PUSH_H
#define NEON_CHAIN_PUSH_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
struct NeonChainPush {
  vec3 offsetY;  // the flow's second potential, drift included (computed in double on the CPU)
  float dt;      // seconds this step
  vec3 offsetZ;  // the third potential, drift included
  float lerp;    // the share of the gap to the particle ahead a follower closes: followerLerp(lerp60, dt)
  uint chainCount;
  uint particlesPerChain;
  float fieldStrength;  // world units per second per unit of curl
  float noiseScale;     // world -> noise coordinates
};
VITRINE_SHARED_END

#endif
