#version 460
// The proxy of the crystal: the octahedron itself, a little larger (kProxyInflation), back faces only,
// so every pixel the crystal covers runs the raymarch once (also with the eye inside) and the chamber's
// other pixels cost nothing. Half the pixels of the bounding box it replaced, which all ran the
// fragment shader only to discard.
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "crystal_push.h"
layout(location = 0) out vec3 world;
layout(push_constant) uniform Push { BloomCrystalPush pc; };

// Room for the antialiased silhouette, which reaches half a pixel outside the crystal: the faces move
// out by 0.023 (0.05 R / sqrt 3), half a pixel wider than 192x108's at the crystal's far side.
const float kProxyInflation = 1.05;

void main() {
  // 24 vertices: a triangle for each octant, its corners on the three half-axes of the octant's signs.
  const int face = gl_VertexIndex / 3, corner = gl_VertexIndex % 3;
  const vec3 signs = vec3((face & 1) != 0 ? 1.0 : -1.0, (face & 2) != 0 ? 1.0 : -1.0, (face & 4) != 0 ? 1.0 : -1.0);
  // Counter-clockwise seen from outside (the winding the pipeline's culling expects): x, y, z when the
  // octant's signs multiply to +1, else x, z, y.
  const int axis = corner == 0 ? 0 : (signs.x * signs.y * signs.z > 0.0) == (corner == 1) ? 1 : 2;
  vec3 p = vec3(0.0);
  p[axis] = signs[axis] * kCrystalRadius * kProxyInflation;
  world = p;
  gl_Position = pc.viewProjection * vec4(world, 1.0);
}
