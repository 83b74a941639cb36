#version 460
// Test-only: tests/isf/speed_field.fs written natively, the same maths, writing linear light straight
// into the frame's rgba16f target (the ISF runner draws display values into rgba8 and decodes them in a
// pass of its own). What the ISF runner's pass costs is measured against this.
#extension GL_GOOGLE_include_directive : require
#include "speed_twin_push.h"
layout(location = 0) in vec2 normCoord;
layout(location = 0) out vec4 colourOut;
layout(push_constant) uniform Push { TestSpeedTwinPush pc; };

float lattice(vec2 cell) {
  uvec2 p = uvec2(ivec2(cell) + 4096);
  uint h = p.x * 1664525u + p.y * 1013904223u;
  h ^= h >> 16;
  h *= 747796405u;
  h ^= h >> 13;
  return float(h & 65535u) / 65535.0;
}

float noise(vec2 p) {
  vec2 cell = floor(p), f = fract(p);
  vec2 u = f * f * (3.0 - 2.0 * f);
  return mix(mix(lattice(cell), lattice(cell + vec2(1.0, 0.0)), u.x),
             mix(lattice(cell + vec2(0.0, 1.0)), lattice(cell + vec2(1.0, 1.0)), u.x), u.y);
}

float fbm(vec2 p) {
  float sum = 0.0, amplitude = 0.5;
  for (int octave = 0; octave < 6; ++octave) {
    sum += amplitude * noise(p);
    p = p * 2.03 + vec2(1.7, 9.2);
    amplitude *= 0.5;
  }
  return sum;
}

vec3 linearFromDisplay(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

void main() {
  vec2 p = normCoord * vec2(pc.renderSize.x / pc.renderSize.y, 1.0) * pc.zoom;
  vec2 q = vec2(fbm(p + 0.1 * pc.time), fbm(p + vec2(5.2, 1.3)));
  vec2 r = vec2(fbm(p + 4.0 * q + vec2(1.7, 9.2)), fbm(p + 4.0 * q + vec2(8.3, 2.8)));
  float f = fbm(p + 4.0 * r);
  vec3 colour = mix(vec3(0.10, 0.20, 0.40), vec3(0.90, 0.60, 0.30), f);
  colour = mix(colour, vec3(0.20, 0.70, 0.60), 0.5 * length(q));
  colourOut = vec4(linearFromDisplay(colour), 1.0);
}
