// What the present pass shows at a pixel of the output, before any transfer function: the scene's
// target scaled onto the output, mixed with the incoming scene's in a cross-fade; and the frame as the
// flash guard's passes see it.
#ifndef HOST_PRESENT_COLOUR_GLSL
#define HOST_PRESENT_COLOUR_GLSL

vec4 presentedColour(sampler2D source, sampler2D incoming, float fade, ivec2 pixel, ivec2 size) {
  vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
  vec4 colour = textureLod(source, uv, 0.0);
  if (fade > 0.0) colour = mix(colour, textureLod(incoming, uv, 0.0), fade);
  return colour;
}

// The flash guard's view of the frame: a texel of `image` at `pixel` of a frame of `size`, exact where the
// image is that size (the guard works on the frame at the target's own size, and every output then
// samples its copy as it would the target), sampled where it is not (an incoming scene rendered at
// another scale).
vec4 frameTexel(sampler2D image, ivec2 pixel, ivec2 size) {
  if (textureSize(image, 0) == size) return texelFetch(image, pixel, 0);
  return textureLod(image, (vec2(pixel) + 0.5) / vec2(size), 0.0);
}

vec4 frameColour(sampler2D source, sampler2D incoming, float fade, ivec2 pixel, ivec2 size) {
  vec4 colour = frameTexel(source, pixel, size);
  if (fade > 0.0) colour = mix(colour, frameTexel(incoming, pixel, size), fade);
  return colour;
}

vec3 linearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

#endif
