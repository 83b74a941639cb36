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
// NeonHeadState::flags: a steered head (a pen) sits at `origin`, where the CPU's pen is, instead of
// swimming, and its chain records the pen's path; a drawn chain (a pen's, during and after the drag)
// keeps the shape it recorded: let go, it stays where it was drawn and fades.
const uint NEON_HEAD_STEERED = 1u;
const uint NEON_HEAD_DRAWN = 2u;
// A pen's chain takes a new point of its path each time the pen has moved 0.6 m from the newest one
// (63 points hold about 38 m of stroke, most of a drag across the frame): the squared distance, as a
// literal both sides round alike (a product folded by the shader compiler might round otherwise).
const float NEON_PEN_SPACING_SQUARED = 0.36;

// The life below which a tube's gas dims (smoothly, to nothing at 0); above it a tube shines at full
// brightness. A drawn tube let go starts its fade here.
const float NEON_FADE_LIFE = 0.34;

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
