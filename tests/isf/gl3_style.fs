/*{
  "DESCRIPTION": "Written as for desktop GL 3.3: a #version line, texture(), its own output variable, integer maths",
  "ISFVSN": "2.0",
  "INPUTS": [
    {"NAME": "cells", "TYPE": "long", "MIN": 1, "MAX": 12, "DEFAULT": 6},
    {"NAME": "edge", "TYPE": "color", "DEFAULT": [0.1, 0.8, 1.0]}
  ]
}*/
#version 330

out vec4 fragColour;

uint hash(uvec2 p) {
  uint h = p.x * 1664525u + p.y * 1013904223u;
  h ^= h >> 16;
  return h * 747796405u;
}

void main() {
  ivec2 cell = ivec2(isf_FragNormCoord * float(cells));
  float shade = float(hash(uvec2(cell) + uint(FRAMEINDEX)) & 255u) / 255.0;
  fragColour = vec4(mix(vec3(shade), edge.rgb, step(0.9, fract(isf_FragNormCoord.x * float(cells)))), 1.0);
}
