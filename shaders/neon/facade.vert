#version 460
// The facade: one instance per box, 36 vertices from the corner bit patterns, in world space.
#extension GL_GOOGLE_include_directive : require
#include "neon/camera.glsl"

struct Box {
  vec4 centre;
  vec4 halfSize;
};
layout(std430, set = 0, binding = 1) readonly buffer Boxes { Box boxes[]; };
layout(location = 0) out vec3 world;
layout(location = 1) flat out vec3 normal;

void main() {
  const int faces[36] = int[36](0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6,
                                1, 3, 5, 3, 7, 5);
  const vec3 faceNormals[6] = vec3[6](vec3(0, 0, -1), vec3(0, 0, 1), vec3(0, -1, 0), vec3(0, 1, 0), vec3(-1, 0, 0),
                                     vec3(1, 0, 0));
  const int corner = faces[gl_VertexIndex];
  const Box box = boxes[gl_InstanceIndex];
  world = box.centre.xyz + (vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1) * 2.0 - 1.0) * box.halfSize.xyz;
  normal = faceNormals[gl_VertexIndex / 6];
  gl_Position = F.viewProjection * vec4(world, 1.0);
}
