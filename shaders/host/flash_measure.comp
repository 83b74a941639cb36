#version 460
// The flash guard, first pass: counts the output's pixels whose colour would make a general or red
// transition against what was shown last frame (the held image), rising and falling apart.
#extension GL_GOOGLE_include_directive : require
#include "flash_guard_blocks.h"
#include "flash_guard.glsl"
#include "present_colour.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1) uniform sampler2D incoming;
layout(binding = 2, rgba16f) uniform readonly image2D held;  // what was shown last frame
layout(binding = 3, std430) buffer FlashGuard { HostFlashGuardState guard; };
layout(push_constant) uniform Push { HostFlashMeasurePush pc; };

shared uint counts[4];

void main() {
  if (gl_LocalInvocationIndex < 4) counts[gl_LocalInvocationIndex] = 0u;
  barrier();
  ivec2 size = imageSize(held);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (all(lessThan(pixel, size))) {
    vec3 now = frameColour(source, incoming, pc.fade, pixel, size).rgb;
    vec3 before = imageLoad(held, pixel).rgb;
    int general = generalTransition(before, now);
    int red = redTransition(before, now);
    if (general > 0) atomicAdd(counts[0], 1u);
    if (general < 0) atomicAdd(counts[1], 1u);
    if (red > 0) atomicAdd(counts[2], 1u);
    if (red < 0) atomicAdd(counts[3], 1u);
  }
  barrier();
  if (gl_LocalInvocationIndex == 0) {
    if (counts[0] > 0u) atomicAdd(guard.generalRising, counts[0]);
    if (counts[1] > 0u) atomicAdd(guard.generalFalling, counts[1]);
    if (counts[2] > 0u) atomicAdd(guard.redRising, counts[2]);
    if (counts[3] > 0u) atomicAdd(guard.redFalling, counts[3]);
  }
}
