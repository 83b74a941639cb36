#version 460
// Carries the vapour over to a lattice of another side (a quality tier's, chosen while the piece
// runs): each voxel inside the crystal takes the old lattice's trilinear value at its centre, both
// lattices spanning the same box, so the vapour keeps its place and its level. Outside stays the
// host's zeros, as diffuse.comp needs. At the same side it is an exact copy.
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;
layout(binding = 0) uniform sampler3D source;
layout(binding = 1, r32f) uniform writeonly image3D lattice;

void main() {
  const int n = imageSize(lattice).x;
  const ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, ivec3(n)))) return;
  if (!insideCrystal(voxelCentre(p, n))) return;
  const float v = textureSize(source, 0).x == n ? texelFetch(source, p, 0).r
                                                : textureLod(source, (vec3(p) + 0.5) / float(n), 0.0).r;
  imageStore(lattice, p, vec4(v));
}
