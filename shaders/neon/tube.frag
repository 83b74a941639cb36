#version 460
// The gas in the tube, in one of three neon colours per chain, added into the tubes' own target: the
// merge pass adds it to the facade, the bloom blurs it into the tube's halo. Seen side-on, a glowing
// cylinder is brightest where the eye looks through the most gas, the chord sqrt(1 - r^2): a round
// profile, saturated across (no white core) and even along the whole tube; at the ends the same
// profile turns round the end point, so the caps are round. The rim is antialiased over a pixel and a
// half. Brightness fades at the end of life and scales by the frame's exposure (the energy budget,
// tube_light.h).
// No depth attachment: light adds in any order, the facade's depth is tested here by hand, and the
// target's alpha keeps the nearest tube's depth and colour (max blending of reverse-Z).
#extension GL_GOOGLE_include_directive : require
#include "neon/camera.glsl"

layout(set = 0, binding = 2) uniform sampler2D facadeDepth;  // r32f, reverse-Z: the facade hides what is behind it

layout(location = 0) in float across;
layout(location = 1) flat in uint colour;
layout(location = 2) in float cap;
layout(location = 3) in float fade;
layout(location = 4) in float rim;
layout(location = 0) out vec4 glow;

void main() {
  if (gl_FragCoord.z < texelFetch(facadeDepth, ivec2(gl_FragCoord.xy), 0).r) discard;
  const float r = length(vec2(across, cap));  // from the tube's axis, or from the end point in a cap
  if (r >= 1.0) discard;  // outside a cap's half disc: nothing to add
  const float chord = sqrt(max(1.0 - r * r, 0.0));
  // A pixel-and-a-half antialiased rim, its width from the vertex shader: screen-space derivatives
  // (fwidth) are coarse on one GPU and fine on another, and differ most where the ribbon bends.
  const float edge = 1.0 - smoothstep(1.0 - rim, 1.0, r);
  const vec3 hue = colour == 0u ? F.colourA : colour == 1u ? F.colourB : F.colourC;
  const float strength = F.glow * F.exposure * (0.3 + 0.7 * chord) * edge * fade;
  // Alpha blends by max: the nearest tube's depth (for the depth of field), with its colour (1..3) in
  // the half float's lowest two mantissa bits, so the max also says which colour is nearest: positive
  // halfs order as their bits do. The merge pass decodes both (merge.comp).
  const uint bits = (packHalf2x16(vec2(gl_FragCoord.z, 0.0)) & 0xfffcu) | (colour + 1u);
  glow = vec4(hue * strength, unpackHalf2x16(bits).x);
}
