#version 460
// The bone-white chamber behind the crystal, in compute (it covers every pixel): a warm white with a
// subtle radial vignette and a soft shadow on the floor under the crystal. The crystal pass then
// draws only the pixels it covers, over this.
#extension GL_GOOGLE_include_directive : require
#include "camera.glsl"
#include "crystal.glsl"
#include "chamber_push.h"
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly image2D target;
layout(push_constant) uniform Push { BloomChamberPush pc; };

const vec3 kBoneWhite = vec3(0.80, 0.76, 0.68);  // linear; about (231, 225, 213) in sRGB
const float kFloor = -1.05;

void main() {
  const ivec2 size = imageSize(target);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  const vec2 uv = (vec2(pixel) + 0.5) / vec2(size);
  const vec3 rd = cameraDirection(uv, float(size.x) / float(size.y));
  vec3 colour = kBoneWhite;
  if (rd.y < 0.0) {  // the floor: a soft contact shadow and, when the crystal glows, its light
    const vec3 p = kEye + rd * ((kFloor - kEye.y) / rd.y);
    const float r2 = dot(p.xz, p.xz);
    colour *= 1.0 - pc.shadow * exp(-r2 / 0.18);
    colour += pc.glow * pc.glowColour * 0.25 * exp(-r2 / 0.35);
  }
  // No horizon line: the chamber is a seamless cove, a touch darker where floor meets wall.
  colour *= 1.0 - 0.05 * exp(-abs(rd.y) * 18.0);
  const vec2 c = uv - 0.5;
  colour *= 1.0 - 0.22 * smoothstep(0.2, 0.85, length(c * vec2(float(size.x) / float(size.y), 1.0)));
  imageStore(target, pixel, vec4(colour, 1.0));
}
