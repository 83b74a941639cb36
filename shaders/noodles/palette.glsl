// Strand colours from the strand index, linear RGB; mirrors src/scenes/noodles/palette.h.
#ifndef NOODLES_PALETTE_GLSL
#define NOODLES_PALETTE_GLSL

const uint COLOURING_GRADIENT = 0u;
const uint COLOURING_HSV = 1u;
const uint COLOURING_GREY = 2u;
const vec3 GRADIENT_FIRST = vec3(0.06, 0.16, 0.55);
const vec3 GRADIENT_LAST = vec3(1.0, 0.62, 0.30);
const float GREY_FIRST = 0.12;

vec3 hsvToRgb(vec3 hsv) {
  vec3 phase = fract(vec3(hsv.x) + vec3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0;
  vec3 hue = clamp(abs(phase) - 1.0, 0.0, 1.0);
  return hsv.z * mix(vec3(1.0), hue, hsv.y);
}

vec3 strandColour(uint strand, uint strands, uint colouring) {
  float t = strands > 1u ? float(strand) / float(strands - 1u) : 0.0;
  if (colouring == COLOURING_HSV) return hsvToRgb(vec3(t * 0.9, 0.4, 1.0));
  if (colouring == COLOURING_GREY) return vec3(mix(GREY_FIRST, 1.0, t));
  return mix(GRADIENT_FIRST, GRADIENT_LAST, t);
}

#endif
