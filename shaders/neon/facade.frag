#version 460
// The facade's light is a texture, looked up with UVs projected along the dominant normal axis.
#extension GL_GOOGLE_include_directive : require
#include "neon/camera.glsl"
#include "neon/facade_uv.glsl"

layout(set = 0, binding = 2) uniform sampler2D lighting;
layout(location = 0) in vec3 world;
layout(location = 1) flat in vec3 normal;
layout(location = 0) out vec4 colour;

void main() {
  colour = vec4(texture(lighting, facadeUv(world, normal, vec2(0.0, 1.0))).rgb, 1.0);
}
