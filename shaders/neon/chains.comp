#version 460
// One invocation per particle of every neon chain: heads swim through curl noise, followers chase the
// particle ahead. Reads last frame's positions, writes this frame's; src/scenes/neon/chains.h is the
// CPU reference for exactly this.
#extension GL_GOOGLE_include_directive : require
#include "common/hash.glsl"
#include "neon/head_state.glsl"
#include "noodles/field.glsl"

layout(local_size_x = 64) in;
layout(binding = 0, std430) readonly buffer Heads { HeadState heads[]; };
layout(binding = 1, std430) readonly buffer Previous { vec4 previous[]; };  // chain-major, k = 0 the head
layout(binding = 2, std430) writeonly buffer Next { vec4 next[]; };

layout(push_constant) uniform Push {
  vec3 offsetY;  // second potential, drift included (computed in double on the CPU)
  float dt;
  vec3 offsetZ;  // third potential, drift included
  float lerp;  // followerLerp(lerp60, dt), computed on the CPU
  uint chainCount;
  uint particlesPerChain;
  float fieldStrength;
  float noiseScale;
} pc;

// Mirrors kLaunchSpeed and launchVelocity in chains.h: a free head's own drift, on top of the flow.
const float kLaunchSpeed = 0.6;
vec3 launchVelocity(uint serial) {
  const float angle = hash01(uvec3(serial, 0x6e656f6eu, 7u)) * 6.2831853;
  return vec3(cos(angle), sin(angle), 0.0) * kLaunchSpeed;
}

void main() {
  // Rows of workgroups are stacked in y when one row cannot hold them all (see chainGroups()).
  uint index = gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * gl_WorkGroupSize.x) + gl_GlobalInvocationID.x;
  if (index >= pc.chainCount * pc.particlesPerChain) return;
  HeadState head = heads[index / pc.particlesPerChain];
  uint k = index % pc.particlesPerChain;
  vec3 position = previous[index].xyz;
  uint state = head.info.x;
  if (state == CHAIN_INITIALISING) {
    position = head.originLife.xyz;
  } else if (state == CHAIN_ALIVE) {
    if (k == 0u && (head.info.w & HEAD_STEERED) != 0u) {
      position = head.originLife.xyz;  // a pen: where the cursor is
    } else if (k == 0u) {
      FieldSettings field = FieldSettings(FIELD_CURL, pc.noiseScale, pc.offsetY, pc.offsetZ, 0.0);
      position += (flowVelocity(position, field) * pc.fieldStrength + launchVelocity(head.info.y)) * pc.dt;
    } else {
      position += (previous[index - 1u].xyz - position) * pc.lerp;
    }
  }
  next[index] = vec4(position, head.originLife.w);
}
