#version 460
// How much of the crystal's interior (insideCore: the drained shell under the surface never
// saturates) is past each event threshold, and the crystal's peak: one workgroup sums its voxels in
// shared memory, then one atomic per counter. Read back a frame or more later (gpu/readback_ring.h).
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "stats_blocks.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;
layout(binding = 0, r32f) uniform readonly image3D view;  // the lattice as the frame's diffusion left it
layout(binding = 1, std430) buffer Stats { BloomLatticeCounts stats; };
layout(push_constant) uniform Push { BloomStatsThresholds thresholds; };  // 0.25 / 0.45 / 0.65 / 0.82 by default

shared uint partial[6];  // interior, above amber, rose, crimson and climax, peak bits

void main() {
  if (gl_LocalInvocationIndex < 6) partial[gl_LocalInvocationIndex] = 0u;
  barrier();
  // Each invocation counts a run of kBloomStatsColumn voxels along z before it touches shared memory:
  // the atomics, not the loads, are what a CPU driver pays for (a 96^3 pass took as long as a diffusion
  // step). The run is clipped to the crystal, as the diffusion's is.
  const int n = imageSize(view).x;
  const ivec2 xy = ivec2(gl_GlobalInvocationID.xy);
  const ivec2 run = xy.x < n && xy.y < n ? crystalColumnRun(xy, n, int(gl_GlobalInvocationID.z), int(kBloomStatsColumn))
                                         : ivec2(0);
  uint mine[5] = uint[5](0u, 0u, 0u, 0u, 0u);
  float peak = 0.0;
  for (int z = run.x; z < run.y; ++z) {
    const ivec3 p = ivec3(xy, z);
    const vec3 normalised = voxelCentre(p, n);
    if (!insideCrystal(normalised)) continue;
    const float v = imageLoad(view, p).r;
    peak = max(peak, v);
    if (!insideCore(normalised)) continue;
    mine[0] += 1u;
    mine[1] += v > thresholds.amber ? 1u : 0u;
    mine[2] += v > thresholds.rose ? 1u : 0u;
    mine[3] += v > thresholds.crimson ? 1u : 0u;
    mine[4] += v > thresholds.climax ? 1u : 0u;
  }
  for (int i = 0; i < 5; ++i)
    if (mine[i] > 0u) atomicAdd(partial[i], mine[i]);
  if (peak > 0.0) atomicMax(partial[5], floatBitsToUint(peak));
  barrier();
  if (gl_LocalInvocationIndex == 0) atomicAdd(stats.interior, partial[0]);
  if (gl_LocalInvocationIndex >= 1 && gl_LocalInvocationIndex < 5)
    atomicAdd(stats.above[gl_LocalInvocationIndex - 1], partial[gl_LocalInvocationIndex]);
  if (gl_LocalInvocationIndex == 5) atomicMax(stats.peakBits, partial[5]);
}
