#version 460
// The gas in the tube: brightest along the core, the glass rim faintly lit, in one of two colours
// per chain, added into the tubes' own target: the merge pass adds it to the facade, the bloom blurs it.
// No depth attachment: light adds in any order, the facade's depth is tested here by hand, and the
// target's alpha keeps the nearest tube's depth (max blending of reverse-Z).
#extension GL_GOOGLE_include_directive : require
#include "neon/camera.glsl"

layout(set = 0, binding = 2) uniform sampler2D facadeDepth;  // r32f, reverse-Z: the facade hides what is behind it

layout(location = 0) in float across;
layout(location = 1) flat in float hue;
layout(location = 2) in float along;
layout(location = 0) out vec4 glow;

void main() {
  if (gl_FragCoord.z < texelFetch(facadeDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
  const float r = abs(across);
  const float core = exp(-r * r * 6.0);                 // the discharge, bright in the middle
  const float rim = smoothstep(0.7, 1.0, r) * 0.25;     // the glass wall catching it
  const vec3 colour = mix(F.colourA.rgb, F.colourB.rgb, hue);
  const vec3 light = colour * F.colourA.w * (core + rim) * (1.0 - 0.5 * along) + vec3(core * core) * 0.15 * F.colourA.w;
  glow = vec4(light, gl_FragCoord.z);  // alpha blends by max: the nearest tube's depth, for the depth of field
}
