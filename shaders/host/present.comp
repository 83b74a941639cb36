#version 460
// Scales the frame onto the output (offscreen image or swapchain image) and, for UNORM swapchains,
// applies the sRGB transfer function. A compute pass rather than vkCmdBlitImage, which is slow on
// compute-first GPUs such as the H100 (docs/PERFORMANCE.md, kifs, Decisions). In kiosk mode's
// cross-fade it also mixes in the incoming scene's target. An output with a warp (a projector: turned,
// mirrored, corner-pinned, edge-blended; src/maths/output_warp.h) is drawn here too, so the scene
// renders once whatever its outputs do with it. With the flash guard on, the frame it scales is the
// guard's (flash_present.comp), made once for every output.
// The warp is a specialisation (constant 0), not a branch: two pipelines, and the plain one carries no
// warp code. On llvmpipe the warp path's mere presence made the plain path 3x slower (a 1280x720
// output: 24 ms against 8), though a uniform branch never took it. (The cross-fade's branch costs
// nothing measurable there, so it stays one.)
#extension GL_GOOGLE_include_directive : require
#include "present_push.h"
#include "present_colour.glsl"
#include "output_warp.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;                     // linear filter, clamped
layout(binding = 1) uniform writeonly image2D destination;        // format from the view
layout(binding = 2) uniform sampler2D incoming;                   // the scene fading in; `source` when none
layout(binding = 3) uniform Warp { HostOutputWarp warp; };         // read only where kWarped
layout(push_constant) uniform Push { HostPresentPush pc; };
layout(constant_id = 0) const int kWarped = 0;  // 1: the output's warp (the Warp block) applies

void main() {
  ivec2 size = imageSize(destination);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  vec4 colour;
  if (kWarped == 0) {  // an output square-on and whole: the plain path, bit for bit
    colour = presentedColour(source, incoming, pc.fade, pixel, size);
  } else {
    vec2 picture;
    if (!unpinOutput(warp, (vec2(pixel) + 0.5) / vec2(size), picture)) {
      imageStore(destination, pixel, vec4(0.0, 0.0, 0.0, 1.0));
      return;
    }
    vec2 uv = warpToSource(warp, picture);
    colour = textureLod(source, uv, 0.0);
    if (pc.fade > 0.0) colour = mix(colour, textureLod(incoming, uv, 0.0), pc.fade);
    colour.rgb *= edgeWeight(warp, picture);
  }
  if (pc.encodeSrgb != 0u) colour.rgb = linearToSrgb(colour.rgb);
  imageStore(destination, pixel, colour);
}
