#version 460
// One step up the bloom chain: level L of the up chain = level L of the down chain + scale * a tent
// upsample of level L + 1 (the up chain's, or for the first step the down chain's smallest level).
// Three different images or mips, so nothing is sampled and written in one dispatch.
// Its push block is neon/bloom_push.h; src/scenes/neon/look.h documents the whole chain.
#extension GL_GOOGLE_include_directive : require
#include "neon/bloom.glsl"
#include "neon/bloom_push.h"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D smaller;                  // level L + 1; linear, clamp to edge
layout(set = 0, binding = 1) uniform sampler2D current;                  // down chain, level L (same size as target)
layout(set = 0, binding = 2, rgba16f) uniform writeonly image2D target;  // up chain, level L
layout(push_constant) uniform Push { NeonBloomUpPush pc; };

void main() {
  const ivec2 size = imageSize(target);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  const vec2 uv = (vec2(p) + 0.5) / vec2(size);
  const vec3 wide = upsampleTent(smaller, uv, pc.radius / vec2(size), pc.smallerLod);
  const vec3 here = texelFetch(current, p, int(pc.currentLod)).rgb;
  imageStore(target, p, vec4(here + pc.scale * wide, 1.0));
}
