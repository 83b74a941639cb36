#version 460
// The proxy of one glass instance: its object-space bounding box turned with the shape (or the
// diamond's exact convex hull), back faces only, so every covered pixel runs the spectral fragment
// shader once, even with the eye inside the proxy.
#extension GL_GOOGLE_include_directive : require
#include "glass/instance.glsl"

layout(std430, set = 0, binding = 4) readonly buffer Hull { GlassHullVertex hull[]; };
layout(location = 0) flat out int instance;

void main() {
  const int faces[36] = int[36](0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4, 2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6,
                                1, 3, 5, 3, 7, 5);
  instance = gl_InstanceIndex;
  vec3 local;
  if (GLASS_SHAPE == SHAPE_DIAMOND) {
    local = hull[gl_VertexIndex].position;
  } else {
    const int corner = faces[gl_VertexIndex];
    // A hair of slack: the sphere trace stops just outside the surface.
    local = (vec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1) * 2.0 - 1.0) * (shapeHalfExtent(glassDims()) + 1.0);
  }
  vec3 world = vec3(F.instances[instance].centre, 0.0) + transpose(mat3(F.rotation)) * local;
  gl_Position = F.viewProjection * vec4(world, 1.0);
}
