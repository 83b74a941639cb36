#version 460
// One step down the bloom chain: reads level L - 1 through a sampler and writes level L (half its size)
// through a storage image, with the 13-tap filter. The first step (L = 1, reading the full-size HDR
// image, the tubes' own light) first keeps only what is bright, through a soft knee, texel by texel at
// full resolution: a tube a pixel or two wide is judged by its own brightness, not by a 6x6 average
// that would dilute it below the threshold (thin tubes would get no glow).
// Its push block is neon/bloom_push.h; src/scenes/neon/look.h documents the whole chain.
#extension GL_GOOGLE_include_directive : require
#include "neon/bloom.glsl"
#include "neon/bloom_push.h"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D source;                   // level L - 1; linear, clamp to edge
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D target;  // level L
layout(push_constant) uniform Push { NeonBloomDownPush pc; };

// Scales the colour so its brightest channel b becomes max(b - threshold, quadratic ease within the
// knee) instead of cutting at the threshold: fades glow in and out smoothly as a tube brightens.
// Scaling all three channels by one factor keeps the hue.
vec3 softThreshold(vec3 c) {
  const float brightness = max(c.r, max(c.g, c.b));
  float soft = clamp(brightness - pc.threshold + pc.knee, 0.0, 2.0 * pc.knee);
  soft = soft * soft / (4.0 * pc.knee + 1e-5);
  return c * (max(soft, brightness - pc.threshold) / max(brightness, 1e-5));
}

void main() {
  const ivec2 size = imageSize(target);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  const vec2 uv = (vec2(p) + 0.5) / vec2(size);
  const vec2 texel = 1.0 / vec2(textureSize(source, int(pc.sourceLod)));
  vec3 c;
  if (pc.prefilter != 0u) {  // a 4x4 tent (1 3 3 1) of thresholded full-resolution texels
    const ivec2 last = textureSize(source, 0) - 1;
    c = vec3(0.0);
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x) {
        const float w = (x == 0 || x == 3 ? 1.0 : 3.0) * (y == 0 || y == 3 ? 1.0 : 3.0);
        c += w * softThreshold(texelFetch(source, clamp(2 * p + ivec2(x, y) - 1, ivec2(0), last), 0).rgb);
      }
    c *= 1.0 / 64.0;
  } else {
    c = downsample13(source, uv, texel, pc.sourceLod);
  }
  // A stray infinity or NaN from the scene would spread over the whole frame as it climbs the chain.
  c = clamp(c, 0.0, 65000.0);
  imageStore(target, p, vec4(c, 1.0));
}
