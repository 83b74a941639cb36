#version 460
// The tubes onto the facade. Where tubes cross, their light adds, but the sum of a pink, a cyan and an
// amber tube is white: so the pixel takes the nearest tube's colour (kept in the tubes' alpha, see
// tube.frag) at the luminance of all their light (nearestColourLight below):
// crossing tubes read as one in front of another, each its own neon colour, at any density. The
// result goes back into the tubes' target for the bloom, and onto the facade (drawn once a size, so read
// here and the sum written to the scene); the nearer of the two depths is kept, so the depth of field
// blurs each by its own distance.
#extension GL_GOOGLE_include_directive : require
#include "neon/merge_push.h"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, rgba16f) uniform readonly image2D facade;
layout(set = 0, binding = 1, r32f) uniform readonly image2D facadeDepth;
layout(set = 0, binding = 2, rgba16f) uniform writeonly image2D scene;  // facade and tubes
layout(set = 0, binding = 3, r32f) uniform writeonly image2D depth;     // the nearer of the two
layout(set = 0, binding = 4, rgba16f) uniform image2D tubes;  // the tubes' light; alpha: the nearest one's depth and colour
layout(push_constant) uniform Push { NeonMergePush pc; };

const vec3 kLuminance = vec3(0.2126, 0.7152, 0.0722);

vec3 nearestColourLight(vec3 sum, vec3 nearest) {
  return nearest * (dot(sum, kLuminance) / max(dot(nearest, kLuminance), 1e-4));
}

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(scene)))) return;
  const vec4 tube = imageLoad(tubes, p);
  const uint bits = packHalf2x16(vec2(tube.a, 0.0)) & 0xffffu;
  const uint colour = bits & 3u;  // 0: no tube here
  const float tubeDepth = unpackHalf2x16(bits & 0xfffcu).x;
  const vec3 light = colour == 0u ? tube.rgb : nearestColourLight(tube.rgb, pc.colours[colour - 1u].rgb);
  imageStore(tubes, p, vec4(light, tubeDepth));
  imageStore(scene, p, imageLoad(facade, p) + vec4(light, 0.0));
  imageStore(depth, p, vec4(max(imageLoad(facadeDepth, p).r, tubeDepth)));
}
