#version 460
// One pass of the vapour's diffusion (bloom_math.h: stageVoxel): an explicit step, or a stage of a
// Runge-Kutta-Legendre super step; 6-neighbour Laplacian with zero-flux edges, Gaussian source, linear
// decay, the octahedral mask, and the clamp at a super step's end.
// Voxels outside the crystal (5/6 of the cube) hold zero in every lattice from its creation on (the
// host clears them; fill.comp fills inside only) and are never written here, so a step moves the
// crystal's bytes, not the cube's. Each invocation walks a run of kBloomDiffuseColumn voxels up z,
// clipped to where its column crosses the crystal, carrying the voxels below and above it from one
// voxel to the next: five loads a voxel instead of seven, and none outside.
// The lattices are storage buffers, x fastest: a warp's 32 voxels along x are one coalesced read on
// the load path, where image loads took the texture path (docs/PERFORMANCE.md: a 256^3 pass 40 ->
// 26 µs on the H200). The crystal samples a filtered image instead, the view, which the frame's last
// stage writes beside its lattice.
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "diffuse_push.h"
layout(local_size_x = 32, local_size_y = 8, local_size_z = 1) in;
layout(binding = 0, std430) readonly buffer Current { float current[]; };
layout(binding = 1, std430) readonly buffer Older { float older[]; };  // the stage before `current`'s
layout(binding = 2, std430) writeonly buffer Next { float next[]; };
layout(binding = 3, r32f) uniform writeonly image3D view;  // the frame's result, for crystal.frag
layout(push_constant) uniform Push { BloomDiffusePush pc; };
// What a stage reads and writes besides its lattices specialises the pipeline (llvmpipe runs the side a
// uniform branch skips too): the stage before's lattice (older weight not 0), and the view (the
// frame's last stage).
layout(constant_id = 0) const uint READS_OLDER = 1u;
layout(constant_id = 1) const uint WRITES_VIEW = 0u;

float at(ivec3 p, int n) { return current[latticeIndex(clamp(p, ivec3(0), ivec3(n - 1)), n)]; }

void main() {
  const int n = int(pc.side);
  const ivec2 xy = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(xy, ivec2(n)))) return;
  const ivec2 run = crystalColumnRun(xy, n, int(gl_GlobalInvocationID.z), int(kBloomDiffuseColumn));
  const int first = run.x, end = run.y;
  if (first >= end) return;
  float below = at(ivec3(xy, first - 1), n), here = at(ivec3(xy, first), n);
  for (int z = first; z < end; ++z) {
    const ivec3 p = ivec3(xy, z);
    const float above = at(p + ivec3(0, 0, 1), n);
    if (insideCrystal(voxelCentre(p, n))) {
      const float sum = at(p + ivec3(-1, 0, 0), n) + at(p + ivec3(1, 0, 0), n) + at(p + ivec3(0, -1, 0), n) +
                        at(p + ivec3(0, 1, 0), n) + below + above;
      float change = pc.diffusion * (sum - 6.0 * here) - pc.decay * here;
      if (pc.sourceRate > 0.0) {  // uniform: venting skips the exponential
        const vec3 d = vec3(p) + 0.5 - pc.source;  // in voxels
        change += pc.sourceRate * exp(-dot(d, d) / (2.0 * pc.sigma * pc.sigma));
      }
      float v = pc.keep * here;
      if (READS_OLDER != 0u) v += pc.older * older[latticeIndex(p, n)];  // an explicit step reads none
      v += pc.dt * change;
      if (pc.last != 0u) v = clamp(v, 0.0, 1.05);  // uniform
      if (WRITES_VIEW != 0u) imageStore(view, p, vec4(v));
      next[latticeIndex(p, n)] = v;
    }
    below = here;
    here = above;
  }
}
