// Mirrors src/maths/color.h.
#ifndef VITRINE_COLOR_GLSL
#define VITRINE_COLOR_GLSL

vec3 acesNarkowicz(vec3 x) {
  return max((x * (2.38 * x - 0.04)) / (x * (2.35 * x + 1.52) + 0.14), vec3(0.0));
}

vec3 srgbToLinear(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

// Relative luminance of linear Rec. 709 / sRGB primaries.
float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

#endif
