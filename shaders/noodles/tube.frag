#version 460
// Lambert plus ambient, the write-up's light; linear output (the host encodes sRGB at the end).
#extension GL_GOOGLE_include_directive : require
#include "noodles/tube_push.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec3 inColour;
layout(location = 2) in float inSide;
layout(location = 0) out vec4 outColour;

const vec3 LIGHT_DIRECTION = vec3(-0.5, -0.2, 1.0) / sqrt(1.29);
const vec3 AMBIENT = vec3(0.05, 0.05, 0.07);

void main() {
  float lambert = max(dot(LIGHT_DIRECTION, normalize(inNormal)), 0.0);
  // The stripe follows the frame's normal: it spirals wherever the frames twist about the strand.
  float paint = pc.stripe != 0u && mod(inSide, 8.0) < 1.0 ? 0.25 : 1.0;
  outColour = vec4(inColour * paint * (lambert + AMBIENT), 1.0);
}
