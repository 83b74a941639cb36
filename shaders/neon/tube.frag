#version 460
// The gas in the tube: brightest along the core, the glass rim faintly lit, in one of two colours
// per chain. Written to the scene and, alone, to the glow target that the bloom blurs.
#extension GL_GOOGLE_include_directive : require
#include "neon/camera.glsl"

layout(location = 0) in float across;
layout(location = 1) flat in float hue;
layout(location = 2) in float along;
layout(location = 0) out vec4 scene;
layout(location = 1) out vec4 glow;

void main() {
  const float r = abs(across);
  const float core = exp(-r * r * 6.0);                 // the discharge, bright in the middle
  const float rim = smoothstep(0.7, 1.0, r) * 0.25;     // the glass wall catching it
  const vec3 colour = mix(F.colourA.rgb, F.colourB.rgb, hue);
  const vec3 light = colour * F.colourA.w * (core + rim) * (1.0 - 0.5 * along) + vec3(core * core) * 0.15 * F.colourA.w;
  scene = vec4(light, 1.0);
  glow = vec4(light, 1.0);
}
