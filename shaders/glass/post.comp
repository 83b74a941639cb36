#version 460
// The accumulated image to the output: the tone map (the seed clips at 1; physical optics rolls HDR
// highlights off with a filmic curve), then optionally FXAA, on tone-mapped colour with its edges
// found in perceptual luminance.
#extension GL_GOOGLE_include_directive : require
#include "common/color.glsl"
#include "glass/optics.glsl"
#include "glass/pass_push.h"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D accumulated;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D target;
layout(constant_id = 0) const uint GLASS_POST_OPTIONS = 0u;  // pass_push.h: GLASS_POST_*
bool postOption(uint bit) { return (GLASS_POST_OPTIONS & bit) != 0u; }

vec3 tone(vec3 c) { return postOption(GLASS_POST_FILMIC) ? filmic(max(c, 0.0)) : clamp(c, 0.0, 1.0); }
vec3 at(vec2 uv) { return tone(textureLod(accumulated, uv, 0.0).rgb); }
float perceptual(vec3 c) { return sqrt(luminance(c)); }

// FXAA in its compact form: the luminance gradient of four diagonal taps gives the edge's direction;
// two or four taps along it are averaged, the wider set only when it stays in the local range.
vec3 fxaa(vec2 uv, vec2 texel) {
  const vec3 m = at(uv);
  const float lm = perceptual(m);
  const float nw = perceptual(at(uv + vec2(-0.5, -0.5) * texel * 2.0));
  const float ne = perceptual(at(uv + vec2(0.5, -0.5) * texel * 2.0));
  const float sw = perceptual(at(uv + vec2(-0.5, 0.5) * texel * 2.0));
  const float se = perceptual(at(uv + vec2(0.5, 0.5) * texel * 2.0));
  const float lo = min(lm, min(min(nw, ne), min(sw, se)));
  const float hi = max(lm, max(max(nw, ne), max(sw, se)));
  if (hi - lo < max(0.0312, hi * 0.125)) return m;  // no edge worth smoothing
  vec2 dir = vec2(-((nw + ne) - (sw + se)), (nw + sw) - (ne + se));
  const float reduce = max((nw + ne + sw + se) * 0.25 * 0.125, 1.0 / 128.0);
  dir = clamp(dir / (min(abs(dir.x), abs(dir.y)) + reduce), -8.0, 8.0) * texel;
  const vec3 a = 0.5 * (at(uv + dir * (1.0 / 3.0 - 0.5)) + at(uv + dir * (2.0 / 3.0 - 0.5)));
  const vec3 b = 0.5 * a + 0.25 * (at(uv - dir * 0.5) + at(uv + dir * 0.5));
  const float lb = perceptual(b);
  return (lb < lo || lb > hi) ? a : b;
}

void main() {
  const ivec2 size = imageSize(target);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  const vec2 texel = 1.0 / vec2(size);
  const vec2 uv = (vec2(p) + 0.5) * texel;
  imageStore(target, p, vec4(postOption(GLASS_POST_FXAA) ? fxaa(uv, texel) : at(uv), 1.0));
}
