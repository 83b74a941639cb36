// One chain's head as the CPU particle engine publishes it; mirrors src/scenes/neon/head_state.h.
#ifndef NEON_HEAD_STATE_GLSL
#define NEON_HEAD_STATE_GLSL

const uint CHAIN_INACTIVE = 0u;
const uint CHAIN_INITIALISING = 1u;
const uint CHAIN_ALIVE = 2u;
const uint HEAD_STEERED = 1u;  // info.w bit: the head sits at originLife.xyz, where the CPU's pen is

struct HeadState {
  vec4 originLife;  // xyz: release position (world), w: life 1..0
  uvec4 info;       // x: state, y: release serial, z: steps since release, w: HEAD_* bits
  vec4 launch;      // xyz: the head's own drift, m/s, on top of the flow (computed on the CPU), w: 0
};

#endif
