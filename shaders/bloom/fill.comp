#version 460
// A new lattice's vapour: `fill` in every voxel inside the crystal (the same test as diffuse.comp's).
// The host clears the lattices to zero first, which is what every voxel outside holds for good; the
// same frame's diffusion then shows it to the crystal (its last stage writes the view).
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "diffuse_push.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;
layout(binding = 0, std430) writeonly buffer Lattice { float lattice[]; };
layout(push_constant) uniform Push { BloomFillPush pc; };

void main() {
  const int n = int(pc.side);
  const ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, ivec3(n)))) return;
  if (insideCrystal(voxelCentre(p, n))) lattice[latticeIndex(p, n)] = pc.fill;
}
