#version 460
// Every pixel once: glass pixels come from the spectral pass, the rest see the backdrop or the
// panorama directly. Then the history: an exponential moving average with weight alpha for the new
// frame, read where this point was last frame (the glass pass's motion), its colour kept within a few
// standard deviations of the history's own running variance (one tap: the second moment of luminance
// rides in alpha), so moving edges do not smear while the spectral noise still averages away.
#extension GL_GOOGLE_include_directive : require
#include "common/color.glsl"
#include "glass/frame.glsl"
#include "glass/pass_push.h"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 1) uniform sampler2D backdrop;
layout(set = 0, binding = 2) uniform sampler2D panorama;
layout(set = 0, binding = 3, rgba16f) uniform readonly image2D colour;
layout(set = 0, binding = 4, rg16f) uniform readonly image2D motion;
layout(set = 0, binding = 5) uniform sampler2D previous;
layout(set = 0, binding = 6, rgba16f) uniform writeonly image2D history;
layout(push_constant) uniform Push { GlassResolvePush pc; };


vec3 background(vec2 pixel) {
  if (F.environment == 0u) return textureLod(backdrop, pixel / F.viewPixels, 0.0).rgb;
  // A skybox: the view direction of a perspective camera, also under the orthographic one.
  vec3 p = pixelToWorld(pixel);
  float camZ = F.orthographic != 0u ? 0.5 * F.viewWorld.y / tan(radians(45.0) * 0.5) : F.eye.z;
  return textureLod(panorama, equirectUv(normalize(p - vec3(0.0, 0.0, camZ))), 0.0).rgb * F.exposure;
}

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(F.viewPixels)))) return;
  const vec2 centre = vec2(p) + 0.5;
  vec4 sample_ = imageLoad(colour, p);
  vec2 moved = vec2(0.0);
  if (sample_.a > 0.0) moved = imageLoad(motion, p).xy;
  else sample_.rgb = background(centre);
  const vec3 current = sample_.rgb;
  const float y = luminance(current);

  vec4 result = vec4(current, y * y);
  if (pc.historyValid != 0u) {
    const vec2 from = centre + (pc.reproject != 0u ? moved : vec2(0.0));
    if (all(greaterThanEqual(from, vec2(0.0))) && all(lessThan(from, F.viewPixels))) {
      vec4 past = textureLod(previous, from / F.viewPixels, 0.0);
      const float mean = luminance(past.rgb);
      const float sigma = sqrt(max(past.a - mean * mean, 0.0));
      const float reach = 3.0 * sigma + 0.05 * max(mean, y) + 0.01;
      past.rgb = clamp(past.rgb, current - reach, current + reach);
      result = mix(past, vec4(current, y * y), pc.alpha);
    }
  }
  imageStore(history, p, result);
}
