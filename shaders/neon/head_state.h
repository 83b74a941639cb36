// One chain's head as the CPU particle engine publishes it each step, one declaration for both sides:
// src/scenes/neon/particle_engine.cpp writes it, the heads buffer carries it as a std430 array,
// shaders/neon/chains.comp reads it. The C++ helpers around it are in src/scenes/neon/head_state.h.
#ifndef NEON_HEAD_STATE_H
#define NEON_HEAD_STATE_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
// NeonHeadState::state.
const uint NEON_CHAIN_INACTIVE = 0u;      // a free slot: the GPU leaves the chain where it is
const uint NEON_CHAIN_INITIALISING = 1u;  // just released: the GPU places the whole chain at the origin
const uint NEON_CHAIN_ALIVE = 2u;         // life falls; the head swims, the followers chase it
// NeonHeadState::flags: a steered head (a pen) sits at `origin`, where the CPU's pen is, instead of swimming.
const uint NEON_HEAD_STEERED = 1u;

struct NeonHeadState {
  vec3 origin;   // release position (world), moved by every steer of a pen
  float life;    // 1 at release down to 0
  uint state;    // NEON_CHAIN_*
  uint serial;   // release serial: 1, 2, ...
  uint steps;    // steps since release
  uint flags;    // NEON_HEAD_* bits
  vec3 launch;   // the head's own drift, m/s, on top of the flow (computed on the CPU: launchVelocity)
  uint padding;  // 0: std430 rounds the struct up to 16 bytes, C++ must too
};
VITRINE_SHARED_END

#endif
