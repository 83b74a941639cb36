#version 460
// Test-only (tests/gpu/frame_resources_test.cpp): destination = (source, sampled over the whole
// destination, when useSource is set) + add. Uniform images stay uniform, so values are exact.
#extension GL_GOOGLE_include_directive : require
#include "accumulate_push.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1, rgba16f) uniform writeonly image2D destination;
layout(push_constant) uniform Push { TestAccumulatePush pc; };

void main() {
  ivec2 size = imageSize(destination);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  vec4 value = pc.useSource != 0u ? textureLod(source, (vec2(pixel) + 0.5) / vec2(size), 0.0) : vec4(0.0);
  imageStore(destination, pixel, value + vec4(pc.add));
}
