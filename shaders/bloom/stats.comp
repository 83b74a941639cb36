#version 460
// How much of the crystal is past each event threshold, and the peak: one workgroup sums its voxels
// in shared memory, then one atomic per counter. Read back a few frames later (gpu/readback_ring.h).
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;
layout(binding = 0, r16f) uniform readonly image3D lattice;
// [0] crystal voxels, [1..4] above the four event thresholds (0.25 / 0.45 / 0.65 / 0.82), [5] peak (float bits: positive floats
// order as their bits do)
layout(binding = 1, std430) buffer Stats { uint counts[8]; } stats;
layout(push_constant) uniform Push { vec4 thresholds; } pc;  // amber, rose, crimson, climax

shared uint partial[6];

void main() {
  if (gl_LocalInvocationIndex < 6) partial[gl_LocalInvocationIndex] = 0u;
  barrier();
  const int n = imageSize(lattice).x;
  const ivec3 p = ivec3(gl_GlobalInvocationID);
  if (all(lessThan(p, ivec3(n))) && insideCrystal((vec3(p) + 0.5) / float(n) * 2.0 - 1.0)) {
    const float v = imageLoad(lattice, p).r;
    atomicAdd(partial[0], 1u);
    if (v > pc.thresholds.x) atomicAdd(partial[1], 1u);
    if (v > pc.thresholds.y) atomicAdd(partial[2], 1u);
    if (v > pc.thresholds.z) atomicAdd(partial[3], 1u);
    if (v > pc.thresholds.w) atomicAdd(partial[4], 1u);
    atomicMax(partial[5], floatBitsToUint(max(v, 0.0)));
  }
  barrier();
  if (gl_LocalInvocationIndex < 5) atomicAdd(stats.counts[gl_LocalInvocationIndex], partial[gl_LocalInvocationIndex]);
  if (gl_LocalInvocationIndex == 5) atomicMax(stats.counts[5], partial[5]);
}
