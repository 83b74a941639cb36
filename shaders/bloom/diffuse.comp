#version 460
// One pass of the vapour's diffusion (bloom_math.h: stageVoxel): an explicit step, or a stage of a
// Runge-Kutta-Legendre super step; 6-neighbour Laplacian with zero-flux edges, Gaussian source, linear
// decay, the octahedral mask, and the clamp at a super step's end.
// Voxels outside the crystal (5/6 of the cube) hold zero in both images from their creation on (the
// host clears them; fill.comp fills inside only) and are never written here, so a step moves the
// crystal's bytes, not the cube's. Each invocation walks a run of kBloomDiffuseColumn voxels up z,
// clipped to where its column crosses the crystal, carrying the voxels below and above it from one
// voxel to the next: five loads a voxel instead of seven, and none outside.
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "diffuse_push.h"
layout(local_size_x = 32, local_size_y = 8, local_size_z = 1) in;
layout(binding = 0, r32f) uniform readonly image3D current;
layout(binding = 1, r32f) uniform readonly image3D older;  // the stage before `current`'s
layout(binding = 2, r32f) uniform writeonly image3D next;
layout(push_constant) uniform Push { BloomDiffusePush pc; };

float at(ivec3 p, int last) { return imageLoad(current, clamp(p, ivec3(0), ivec3(last))).r; }

void main() {
  const int n = imageSize(current).x, last = n - 1;
  const ivec2 xy = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(xy, ivec2(n)))) return;
  const ivec2 run = crystalColumnRun(xy, n, int(gl_GlobalInvocationID.z), int(kBloomDiffuseColumn));
  const int first = run.x, end = run.y;
  if (first >= end) return;
  float below = at(ivec3(xy, first - 1), last), here = at(ivec3(xy, first), last);
  for (int z = first; z < end; ++z) {
    const ivec3 p = ivec3(xy, z);
    const float above = at(p + ivec3(0, 0, 1), last);
    if (insideCrystal(voxelCentre(p, n))) {
      const float sum = at(p + ivec3(-1, 0, 0), last) + at(p + ivec3(1, 0, 0), last) + at(p + ivec3(0, -1, 0), last) +
                        at(p + ivec3(0, 1, 0), last) + below + above;
      float change = pc.diffusion * (sum - 6.0 * here) - pc.decay * here;
      if (pc.sourceRate > 0.0) {  // uniform: venting skips the exponential
        const vec3 d = vec3(p) + 0.5 - pc.source;  // in voxels
        change += pc.sourceRate * exp(-dot(d, d) / (2.0 * pc.sigma * pc.sigma));
      }
      float v = pc.keep * here;
      if (pc.older != 0.0) v += pc.older * imageLoad(older, p).r;  // uniform: an explicit step reads none
      v += pc.dt * change;
      imageStore(next, p, vec4(pc.last != 0u ? clamp(v, 0.0, 1.05) : v));
    }
    below = here;
    here = above;
  }
}
