#version 460
// Carries the vapour over to a lattice of another side (a quality tier's, chosen while the piece
// runs): each voxel inside the crystal takes the old lattice's trilinear value at its centre, read
// from the old view (the image the crystal samples, which holds the lattice as its last step left
// it), both spanning the same box, so the vapour keeps its place and its level. Outside stays the
// host's zeros, as diffuse.comp needs.
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "diffuse_push.h"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;
layout(binding = 0) uniform sampler3D source;
layout(binding = 1, std430) writeonly buffer Lattice { float lattice[]; };
layout(push_constant) uniform Push { BloomResamplePush pc; };

void main() {
  const int n = int(pc.side);
  const ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, ivec3(n)))) return;
  if (insideCrystal(voxelCentre(p, n))) lattice[latticeIndex(p, n)] = textureLod(source, (vec3(p) + 0.5) / float(n), 0.0).r;
}
