#version 460
// The backdrop's top level, whenever its source or the view changes: the photo covering the view, or
// a gradient or checker; for the page, paper for the text that the text pass sets next.
#extension GL_GOOGLE_include_directive : require
#include "common/color.glsl"
#include "glass/pass_push.h"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D photo;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D backdrop;
layout(push_constant) uniform Push { GlassComposePush pc; };

void main() {
  const ivec2 size = imageSize(backdrop);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  const vec2 uv = (vec2(p) + 0.5) / vec2(size);
  vec3 c;
  if (pc.source == GLASS_SOURCE_PHOTO) {
    c = textureLod(photo, (uv - 0.5) * pc.photoScale + 0.5, 0.0).rgb;
  } else if (pc.source == GLASS_SOURCE_CHECKER) {  // a checker of 48 reference pixels, light and dark grey
    const ivec2 cell = ivec2(floor(vec2(p) / (48.0 * float(size.y) / 1073.0)));
    c = ((cell.x + cell.y) & 1) == 0 ? vec3(0.8) : vec3(0.08);
  } else {  // dusk: deep blue overhead to a warm horizon, a soft sun low on the right
    const vec3 top = srgbToLinear(vec3(0.10, 0.13, 0.32));
    const vec3 horizon = srgbToLinear(vec3(0.98, 0.55, 0.32));
    c = mix(top, horizon, smoothstep(0.0, 1.0, uv.y));
    const float sun = length((uv - vec2(0.72, 0.7)) * vec2(float(size.x) / float(size.y), 1.0));
    c += srgbToLinear(vec3(1.0, 0.85, 0.6)) * exp(-sun * sun * 60.0);
  }
  if (pc.paper != 0u && float(p.x) >= pc.paperLeft && float(p.x) < pc.paperRight) {
    c = mix(c, srgbToLinear(vec3(0.95, 0.93, 0.88)), 0.88);  // paper, with the photo faintly through it
  }
  imageStore(backdrop, p, vec4(c, 1.0));
}
