// The present pass's half of src/maths/output_warp.h, line for line.
#ifndef HOST_OUTPUT_WARP_GLSL
#define HOST_OUTPUT_WARP_GLSL
#include "output_warp.h"

// The picture's square position an output position shows; false where the pinned picture does not reach.
bool unpinOutput(HostOutputWarp w, vec2 position, out vec2 picture) {
  vec3 o = vec3(position, 1.0);
  vec3 q = vec3(dot(w.unpin0.xyz, o), dot(w.unpin1.xyz, o), dot(w.unpin2.xyz, o));
  if (!(q.z > 0.0)) return false;
  picture = q.xy / q.z;
  return all(greaterThanEqual(picture, vec2(0.0))) && all(lessThanEqual(picture, vec2(1.0)));
}

vec2 warpToSource(HostOutputWarp w, vec2 picture) {
  vec3 p = vec3(picture, 1.0);
  return vec2(dot(w.sourceU.xyz, p), dot(w.sourceV.xyz, p));
}

float edgeRamp(float d, float width, float curve, float gamma) {
  if (!(width > 0.0)) return 1.0;
  float x = clamp(d / width, 0.0, 1.0);
  float s = x < 0.5 ? 0.5 * pow(2.0 * x, curve) : 1.0 - 0.5 * pow(2.0 * (1.0 - x), curve);
  return pow(s, 1.0 / gamma);
}

float edgeWeight(HostOutputWarp w, vec2 picture) {
  float curve = w.blendCurve.x, gamma = w.blendCurve.y;
  return edgeRamp(picture.x, w.blendWidths.x, curve, gamma) * edgeRamp(1.0 - picture.x, w.blendWidths.z, curve, gamma) *
         edgeRamp(picture.y, w.blendWidths.y, curve, gamma) * edgeRamp(1.0 - picture.y, w.blendWidths.w, curve, gamma);
}

#endif
