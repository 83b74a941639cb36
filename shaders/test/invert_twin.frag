#version 460
// Test-only: tests/isf/filter_invert.fs written natively, the same work as the ISF runner's three
// passes in one: the frame's linear light sampled where the fragment is, encoded to display values,
// turned over by the amount, and decoded back into the target.
#extension GL_GOOGLE_include_directive : require
#include "invert_twin_push.h"
layout(location = 0) out vec4 colourOut;
layout(binding = 0) uniform sampler2D source;
layout(push_constant) uniform Push { TestInvertTwinPush pc; };

vec3 displayFromLinear(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

vec3 linearFromDisplay(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

void main() {
  vec4 colour = texture(source, gl_FragCoord.xy / vec2(textureSize(source, 0)));
  vec3 display = displayFromLinear(colour.rgb);
  colourOut = vec4(linearFromDisplay(mix(display, 1.0 - display, pc.amount)), colour.a);
}
