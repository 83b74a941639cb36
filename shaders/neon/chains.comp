#version 460
// One invocation per particle of every neon chain: heads swim through curl noise, followers chase the
// particle ahead. Reads last frame's positions, writes this frame's; src/scenes/neon/chains.h is the
// CPU reference for exactly this, bit for bit: positions are integrated frame after frame, so a
// last-bit difference between drivers would grow over a run instead of staying put. Every floating-point
// operation on the way is an add, subtract, multiply, floor or conversion, which Vulkan rounds
// correctly, and `precise` (NOISE_EXACT for the field) forbids fusing them; the one transcendental,
// the launch direction, comes from the CPU in NeonHeadState::launch.
#extension GL_GOOGLE_include_directive : require
#define NOISE_EXACT
#include "neon/chain_push.h"
#include "neon/head_state.h"
#include "common/flow_field.glsl"

layout(local_size_x = 64) in;
layout(binding = 0, std430) readonly buffer Heads { NeonHeadState heads[]; };
layout(binding = 1, std430) readonly buffer Previous { vec4 previous[]; };  // chain-major, k = 0 the head
layout(binding = 2, std430) writeonly buffer Next { vec4 next[]; };

layout(push_constant) uniform Push { NeonChainPush pc; };

void main() {
  // Rows of workgroups are stacked in y when one row cannot hold them all (see chainGroups()).
  uint index = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (index >= pc.chainCount * pc.particlesPerChain) return;
  NeonHeadState head = heads[index / pc.particlesPerChain];
  uint k = index % pc.particlesPerChain;
  precise vec3 position = previous[index].xyz;
  uint state = head.state;
  const bool steered = (head.flags & NEON_HEAD_STEERED) != 0u, drawn = (head.flags & NEON_HEAD_DRAWN) != 0u;
  if (state == NEON_CHAIN_INITIALISING) {
    position = head.origin;
  } else if (state == NEON_CHAIN_ALIVE && steered) {
    // A pen records its path: a point every 0.6 m, the chain shifting one place down (chains.h).
    precise vec3 gap = head.origin - previous[index - k + 1u].xyz;
    precise float squared = gap.x * gap.x + gap.y * gap.y + gap.z * gap.z;
    if (k == 0u || (k == 1u && squared >= NEON_PEN_SPACING_SQUARED)) {
      position = head.origin;  // where the cursor is
    } else if (squared >= NEON_PEN_SPACING_SQUARED) {
      position = previous[index - 1u].xyz;
    }
  } else if (state == NEON_CHAIN_ALIVE && !drawn) {
    if (k == 0u) {
      FieldSettings field = FieldSettings(FIELD_CURL, pc.noiseScale, pc.offsetY, pc.offsetZ, 0.0);
      position += (flowVelocity(position, field) * pc.fieldStrength + head.launch) * pc.dt;
    } else {
      position += (previous[index - 1u].xyz - position) * pc.lerp;
    }
  }  // a drawn chain let go stays as drawn while it fades
  next[index] = vec4(position, head.life);
}
