#version 460
// The flash guard's frame: the scene's target (the incoming scene mixed in during a fade), texel for
// texel, except where this frame's general or red transitions were not admitted (flash_decide.comp):
// there the pixels that would make such a transition keep what was shown last frame. A frame whose
// transitions were admitted is copied exactly, so the outputs that present it show what they would
// show of the target. It is written into the held image, which the outputs present and the next frame
// is measured against: one image, not a copy of it.
#extension GL_GOOGLE_include_directive : require
#include "flash_guard_blocks.h"
#include "flash_guard.glsl"
#include "present_colour.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 2) uniform sampler2D incoming;
layout(binding = 3, rgba16f) uniform image2D held;
layout(binding = 4, std430) readonly buffer FlashGuard { HostFlashGuardState guard; };
layout(push_constant) uniform Push { HostFlashPresentPush pc; };

void main() {
  ivec2 size = imageSize(held);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  vec4 colour = frameColour(source, incoming, pc.fade, pixel, size);
  if (pc.historyValid != 0u) {
    vec4 before = imageLoad(held, pixel);
    bool general = guard.showGeneral == 0u && generalTransition(before.rgb, colour.rgb) != 0;
    bool red = guard.showRed == 0u && redTransition(before.rgb, colour.rgb) != 0;
    if (general || red) colour = before;
  }
  imageStore(held, pixel, colour);  // what is shown, and what the next frame is measured against
}
