#version 460
// The render-pass path: the instanced proxy's fragments, each shading its own pixel through its own
// instance (shade.glsl), so only covered pixels pay; the surface's own depth sorts overlapping instances.
#extension GL_GOOGLE_include_directive : require
#include "glass/shade.glsl"

layout(location = 0) flat in int instance;
layout(location = 0) out vec4 colour;  // a = 1: covered by glass (the resolve pass fills the rest)
layout(location = 1) out vec2 motion;

const vec3 PROXY_TINT = vec3(1.0, 0.2, 0.6);

void main() {
  Shaded shaded;
  const bool showProxy = F.showProxy != 0u;
  if (!shadeGlass(gl_FragCoord.xy, instance, shaded)) {
    if (!showProxy) discard;
    shaded = Shaded(PROXY_TINT, vec2(0.0), 1e9);  // the rasterised silhouette around the glass
  }
  colour = vec4(showProxy ? mix(shaded.colour, PROXY_TINT, 0.25) : shaded.colour, 1.0);
  motion = shaded.motion;
  gl_FragDepth = 1.0 / (1.0 + shaded.eyeDistance * 1e-3);  // reverse depth: nearer is larger
}
