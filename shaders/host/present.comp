#version 460
// Scales the scene's HDR target onto the output (offscreen image or swapchain image) and, for UNORM
// swapchains, applies the sRGB transfer function. A compute pass rather than vkCmdBlitImage: on
// compute-first GPUs such as the H100 a 4K blit took 1.19 ms, this pass a small fraction of that.
// In kiosk mode's cross-fade it also mixes in the incoming scene's target. An output with a warp (a
// projector: turned, mirrored, corner-pinned, edge-blended; src/maths/output_warp.h) is drawn here too,
// so the scene renders once whatever its outputs do with it.
#extension GL_GOOGLE_include_directive : require
#include "present_push.h"
#include "output_warp.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;                     // linear filter, clamped
layout(binding = 1) uniform writeonly image2D destination;        // format from the view
layout(binding = 2) uniform sampler2D incoming;                   // the scene fading in; `source` when none
layout(binding = 3) uniform Warp { HostOutputWarp warp; };         // read only when pc.warp != 0
layout(push_constant) uniform Push { HostPresentPush pc; };

vec3 linearToSrgb(vec3 c) {
  c = clamp(c, 0.0, 1.0);
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}

void main() {
  ivec2 size = imageSize(destination);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
  float light = 1.0;
  if (pc.warp != 0u) {  // an output square-on and whole skips this: its pixels are the plain path's, bit for bit
    vec2 picture;
    if (!unpinOutput(warp, uv, picture)) {
      imageStore(destination, pixel, vec4(0.0, 0.0, 0.0, 1.0));
      return;
    }
    light = edgeWeight(warp, picture);
    uv = warpToSource(warp, picture);
  }
  vec4 colour = textureLod(source, uv, 0.0);
  if (pc.fade > 0.0) colour = mix(colour, textureLod(incoming, uv, 0.0), pc.fade);
  colour.rgb *= light;
  if (pc.encodeSrgb != 0u) colour.rgb = linearToSrgb(colour.rgb);
  imageStore(destination, pixel, colour);
}
