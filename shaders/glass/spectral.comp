#version 460
// The compute path: the same per-pixel shading as the proxy's fragments (shade.glsl), for GPUs whose
// graphics part is a sliver of the chip (the H100's two graphics-capable TPCs). Each pixel finds the
// front hits of the instances whose screen rectangle holds it, shades the nearest once, and pixels no
// glass covers cost a few comparisons.
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
  // The nearest front hit of the instances whose screen rectangle holds the pixel, then one shading:
  // the instances' rectangles overlap, and shading is most of the work.
  vec3 rayOrigin, rayDir;
  glassPrimaryRay(fragCoord, rayOrigin, rayDir);
  FrontHit nearest;
  nearest.eyeDistance = SHAPE_FAR;
  int seen = -1;
  bool inRect = false;
  for (int i = 0; i < F.instanceCount; ++i) {
    const vec4 rect = F.instances[i].screenRect;
    if (any(lessThan(fragCoord, rect.xy)) || any(greaterThan(fragCoord, rect.zw))) continue;
    inRect = true;
    FrontHit hit;
    if (glassFrontHit(rayOrigin, rayDir, i, hit) && hit.eyeDistance < nearest.eyeDistance) {
      nearest = hit;
      seen = i;
    }
  }
  const bool covered = seen >= 0;
  Shaded best = Shaded(vec3(0.0), vec2(0.0), 1e30);
  if (covered) best = shadeFrontHit(fragCoord, seen, nearest);
  vec4 colour = covered ? vec4(best.colour, 1.0) : vec4(0.0);
  if (showProxy && inRect) colour = vec4(covered ? mix(best.colour, vec3(1.0, 0.2, 0.6), 0.25) : vec3(1.0, 0.2, 0.6), 1.0);
  imageStore(colourOut, p, colour);
  imageStore(motionOut, p, vec4(best.motion, 0.0, 0.0));
}
