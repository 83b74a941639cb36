#version 460
// The compute path: the same per-pixel shading as the proxy's fragments (shade.glsl), for GPUs whose
// graphics part is a sliver of the chip (the H100's two graphics-capable TPCs). Each pixel tests the
// instances whose screen rectangle holds it, keeps the nearest surface, and pixels no glass covers cost
// a few comparisons.
#extension GL_GOOGLE_include_directive : require
#include "glass/shade.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 4, rgba16f) uniform writeonly image2D colourOut;  // a = 1 where glass covers
layout(set = 0, binding = 5, rg16f) uniform writeonly image2D motionOut;

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(F.viewPixels)))) return;
  const vec2 fragCoord = vec2(p) + 0.5;
  const bool showProxy = F.showProxy != 0u;
  Shaded best = Shaded(vec3(0.0), vec2(0.0), 1e30);
  bool covered = false, inRect = false;
  for (int i = 0; i < F.instanceCount; ++i) {
    const vec4 rect = F.instances[i].screenRect;
    if (any(lessThan(fragCoord, rect.xy)) || any(greaterThan(fragCoord, rect.zw))) continue;
    inRect = true;
    Shaded shaded;
    if (shadeGlass(fragCoord, i, shaded) && shaded.eyeDistance < best.eyeDistance) {
      best = shaded;
      covered = true;
    }
  }
  vec4 colour = covered ? vec4(best.colour, 1.0) : vec4(0.0);
  if (showProxy && inRect) colour = vec4(covered ? mix(best.colour, vec3(1.0, 0.2, 0.6), 0.25) : vec3(1.0, 0.2, 0.6), 1.0);
  imageStore(colourOut, p, colour);
  imageStore(motionOut, p, vec4(best.motion, 0.0, 0.0));
}
