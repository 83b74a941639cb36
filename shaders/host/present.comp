#version 460
// Scales the scene's HDR target onto the output (offscreen image or swapchain image) and, for UNORM
// swapchains, applies the sRGB transfer function. A compute pass rather than vkCmdBlitImage: on
// compute-first GPUs such as the H100 a 4K blit took 1.19 ms, this pass a small fraction of that.
// In kiosk mode's cross-fade it also mixes in the incoming scene's target. With the flash guard on,
// flash_present.comp does the same and may hold pixels back.
#extension GL_GOOGLE_include_directive : require
#include "present_push.h"
#include "present_colour.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;                     // linear filter, clamped
layout(binding = 1) uniform writeonly image2D destination;        // format from the view
layout(binding = 2) uniform sampler2D incoming;                   // the scene fading in; `source` when none
layout(push_constant) uniform Push { HostPresentPush pc; };

void main() {
  ivec2 size = imageSize(destination);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  vec4 colour = presentedColour(source, incoming, pc.fade, pixel, size);
  if (pc.encodeSrgb != 0u) colour.rgb = linearToSrgb(colour.rgb);
  imageStore(destination, pixel, colour);
}
