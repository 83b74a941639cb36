#version 460
// One explicit diffusion step of the vapour lattice (bloom_math.h: diffuseVoxel): 6-neighbour
// Laplacian with zero-flux edges, Gaussian source, linear decay, the octahedral mask, clamp.
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "diffuse_push.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;
layout(binding = 0, r32f) uniform readonly image3D current;
layout(binding = 1, r32f) uniform writeonly image3D next;
layout(push_constant) uniform Push { BloomDiffusePush pc; };

float at(ivec3 p, int last) { return imageLoad(current, clamp(p, ivec3(0), ivec3(last))).r; }

void main() {
  const int n = imageSize(current).x;
  const ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, ivec3(n)))) return;
  const vec3 centre = vec3(p) + 0.5;
  if (!insideCrystal(centre / float(n) * 2.0 - 1.0)) {
    imageStore(next, p, vec4(0.0));
    return;
  }
  const int last = n - 1;
  const float cur = at(p, last);
  const float sum = at(p + ivec3(-1, 0, 0), last) + at(p + ivec3(1, 0, 0), last) + at(p + ivec3(0, -1, 0), last) +
                    at(p + ivec3(0, 1, 0), last) + at(p + ivec3(0, 0, -1), last) + at(p + ivec3(0, 0, 1), last);
  float v = cur + pc.diffusion * (sum - 6.0 * cur) * pc.dt;
  if (pc.sourceRate > 0.0) {  // uniform: venting skips the exponential
    const vec3 d = centre - pc.source;
    v += pc.sourceRate * exp(-dot(d, d) / (2.0 * pc.sigma * pc.sigma)) * pc.dt;
  }
  v -= pc.decay * v * pc.dt;
  imageStore(next, p, vec4(clamp(v, 0.0, 1.05)));
}
