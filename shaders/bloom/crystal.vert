#version 460
// The proxy of the crystal: its bounding box, back faces only, so every covered pixel runs the
// raymarch once (also with the eye inside the box) and the chamber's other pixels cost nothing.
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "crystal_push.h"
layout(location = 0) out vec3 world;
layout(push_constant) uniform Push { BloomCrystalPush pc; };

void main() {
  // 36 vertices: 6 faces x 2 triangles, from bit patterns of the 8 corners.
  const int faces[36] = int[36](0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6,
                                1, 3, 5, 3, 7, 5);
  const int corner = faces[gl_VertexIndex];
  world = (vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1) * 2.0 - 1.0) * kCrystalRadius * 1.02;
  gl_Position = pc.viewProjection * vec4(world, 1.0);
}
