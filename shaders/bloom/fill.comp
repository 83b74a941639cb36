#version 460
// A new lattice's vapour: `fill` in every voxel inside the crystal (the same test as diffuse.comp's).
// The host clears the pair to zero first, which is what every voxel outside holds for good.
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "diffuse_push.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;
layout(binding = 0, r32f) uniform writeonly image3D lattice;
layout(push_constant) uniform Push { BloomFillPush pc; };

void main() {
  const int n = imageSize(lattice).x;
  const ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, ivec3(n)))) return;
  if (insideCrystal(voxelCentre(p, n))) imageStore(lattice, p, vec4(pc.fill));
}
