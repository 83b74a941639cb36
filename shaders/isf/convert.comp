#version 460
// Between Vitrine's frames and an ISF file's images: a vertical flip (Vitrine stores pictures top row
// first, ISF bottom row first, as GL does) and a change of encoding (Vitrine's frames are linear
// light; an ISF shader computes on the values a GL host puts on the screen, sRGB-encoded). The
// runner's output comes out through it, and a filter's or transition's frames go in through it. The
// curve is extended to values above 1 and mirrored below 0, so HDR light and negative values survive
// the way in and back.
#extension GL_GOOGLE_include_directive : require
#include "isf/convert_push.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1, rgba16f) uniform writeonly image2D target;
layout(push_constant) uniform Push { IsfConvertPush pc; };

vec3 decode(vec3 c) {
  vec3 a = abs(c);
  return sign(c) * mix(a / 12.92, pow((a + 0.055) / 1.055, vec3(2.4)), step(0.04045, a));
}

vec3 encode(vec3 c) {
  vec3 a = abs(c);
  return sign(c) * mix(a * 12.92, 1.055 * pow(a, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, a));
}

void main() {
  const ivec2 size = imageSize(target);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  // Pixel centres, so a source of another size (a frame at another scale) is resampled, not cropped.
  const vec2 uv = (vec2(p.x, size.y - 1 - p.y) + 0.5) / vec2(size);
  vec4 c = textureLod(source, uv, 0.0);
  c.rgb = pc.toLinear != 0u ? decode(c.rgb) : encode(c.rgb);
  imageStore(target, p, c);
}
