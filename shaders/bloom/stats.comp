#version 460
// How much of the crystal's interior (insideCore: the drained shell under the surface never
// saturates) is past each event threshold, and the crystal's peak: one workgroup sums its voxels in
// shared memory, then one atomic per counter. Read back a frame or more later (gpu/readback_ring.h).
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;
layout(binding = 0, r32f) uniform readonly image3D lattice;
// [0] interior voxels, [1..4] above the four event thresholds (0.25 / 0.45 / 0.65 / 0.82), [5] peak (float bits: positive floats
// order as their bits do)
layout(binding = 1, std430) buffer Stats { uint counts[8]; } stats;
layout(push_constant) uniform Push { vec4 thresholds; } pc;  // amber, rose, crimson, climax

shared uint partial[6];
const int kColumn = 8;  // voxels along z per invocation; mirrors kStatsColumn in bloom_scene.cpp

void main() {
  if (gl_LocalInvocationIndex < 6) partial[gl_LocalInvocationIndex] = 0u;
  barrier();
  // Each invocation counts a column of kColumn voxels along z before it touches shared memory: the
  // atomics, not the loads, are what a CPU driver pays for (a 96^3 pass took as long as a diffusion step).
  const int n = imageSize(lattice).x;
  uint mine[5] = uint[5](0u, 0u, 0u, 0u, 0u);
  float peak = 0.0;
  for (int k = 0; k < kColumn; ++k) {
    const ivec3 p = ivec3(gl_GlobalInvocationID.xy, int(gl_GlobalInvocationID.z) * kColumn + k);
    const vec3 normalised = (vec3(p) + 0.5) / float(n) * 2.0 - 1.0;
    if (any(greaterThanEqual(p, ivec3(n))) || !insideCrystal(normalised)) continue;
    const float v = imageLoad(lattice, p).r;
    peak = max(peak, v);
    if (!insideCore(normalised)) continue;
    mine[0] += 1u;
    mine[1] += v > pc.thresholds.x ? 1u : 0u;
    mine[2] += v > pc.thresholds.y ? 1u : 0u;
    mine[3] += v > pc.thresholds.z ? 1u : 0u;
    mine[4] += v > pc.thresholds.w ? 1u : 0u;
  }
  for (int i = 0; i < 5; ++i)
    if (mine[i] > 0u) atomicAdd(partial[i], mine[i]);
  if (peak > 0.0) atomicMax(partial[5], floatBitsToUint(peak));
  barrier();
  if (gl_LocalInvocationIndex < 5) atomicAdd(stats.counts[gl_LocalInvocationIndex], partial[gl_LocalInvocationIndex]);
  if (gl_LocalInvocationIndex == 5) atomicMax(stats.counts[5], partial[5]);
}
