#version 460
// The facade, ray cast in compute (full-screen work, which the H100 does far faster in compute than in
// its two graphics TPCs): each pixel's ray meets the nearest of the boxes, whose light comes from the
// lighting texture through UVs projected along the dominant normal axis (the ground has its own).
// Writes the HDR colour and the reverse-Z depth (near / distance along the view; 0 for the sky) that
// the tubes and the depth of field read.
#extension GL_GOOGLE_include_directive : require
#include "neon/camera.glsl"
#include "neon/facade_blocks.h"
#include "neon/facade_uv.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, set = 0, binding = 1) readonly buffer Boxes { NeonFacadeBox boxes[]; };
layout(set = 0, binding = 2) uniform sampler2D lighting;
layout(set = 0, binding = 3, rgba16f) uniform writeonly image2D colour;
layout(set = 0, binding = 4, r32f) uniform writeonly image2D depth;
layout(push_constant) uniform Push { NeonFacadePush pc; };

void main() {
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(F.frameWidth, F.frameHeight)))) return;
  const vec3 dir = pixelRay(vec2(p) + 0.5);
  const vec3 inverse = 1.0 / mix(dir, vec3(1e-20), lessThan(abs(dir), vec3(1e-20)));
  float nearest = 1e30;
  vec3 normal = vec3(0.0);
  for (uint i = 0u; i < F.boxes; ++i) {
    // The slab test: where the ray is inside all three slabs of the box.
    const vec3 t0 = (boxes[i].centre.xyz - boxes[i].halfSize.xyz - F.eye) * inverse;
    const vec3 t1 = (boxes[i].centre.xyz + boxes[i].halfSize.xyz - F.eye) * inverse;
    const vec3 lo = min(t0, t1), hi = max(t0, t1);
    const float enter = max(max(lo.x, lo.y), lo.z), leave = min(min(hi.x, hi.y), hi.z);
    if (enter <= leave && enter > 0.0 && enter < nearest) {
      nearest = enter;
      // The entry face: the axis whose slab was entered last, facing the ray.
      normal = -sign(dir) * step(vec3(enter), lo);
    }
  }
  if (nearest == 1e30) {
    imageStore(colour, p, vec4(pc.sky, 1.0));
    imageStore(depth, p, vec4(0.0));
    return;
  }
  const vec3 hit = F.eye + dir * nearest;
  // The walls from the lighting texture; the ground (up-facing, at the foot) its own wet surface.
  const float ground = step(0.5, normal.y) * step(hit.y, kGroundTop);
  const vec3 wall = textureLod(lighting, facadeUv(hit, normal, vec2(0.0, 1.0)), 0.0).rgb;
  const vec3 lit = mix(wall, groundLight(hit), ground);
  imageStore(colour, p, vec4(lit * pc.facadeBrightness, 1.0));
  imageStore(depth, p, vec4(F.near / (nearest * dot(dir, F.forward))));
}
