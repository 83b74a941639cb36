#version 460
// The whole KIFS picture in one compute pass: march, colour, tonemap, grain and dither, written as
// linear HDR. Emission-only: every sample adds light, nothing absorbs, so no sample order matters.
#extension GL_GOOGLE_include_directive : require
#include "common/color.glsl"
#include "common/hash.glsl"
#include "kifs/field.glsl"
#include "kifs/march_push.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly image2D target;

layout(push_constant) uniform Push { KifsMarchPush pc; };
// The teaching stage, 1..9, is a specialization constant: each stage's pipeline keeps only its own
// field and colour. A uniform branch costs a GPU little, but llvmpipe paid for the stages not shown
// (docs/PERFORMANCE.md, kifs, Decisions).
layout(constant_id = 0) const int KIFS_STAGE = 9;

const vec3 NAVY = vec3(0.027, 0.043, 0.098);

void main() {
  ivec2 size = imageSize(target);
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;

  // y up, the height spanning -0.5..0.5, as in the write-up.
  vec2 uv = (vec2(pixel) + 0.5 - 0.5 * vec2(size)) / float(size.y);
  uv.y = -uv.y;
  vec3 ro = tumble(vec3(0.0, 0.0, -4.5), KIFS_STAGE, pc.angles);
  vec3 rd = tumble(normalize(vec3(uv, 1.0)), KIFS_STAGE, pc.angles);
  uvec2 up = uvec2(pixel);

  // The march is marchGlow in src/scenes/kifs/kifs_math.h.
  // Stage 9: jitter the ray start so neighbouring pixels sample the volume out of step.
  float t = KIFS_STAGE >= 9 ? hash01(uvec3(up, pc.jitterFrame * 3u + pc.seed * 7919u)) * 0.05 : 0.0;
  vec3 glow = vec3(0.0);
  for (int i = 0; i < pc.maxSteps; ++i) {
    vec3 trap;
    float d = field(ro + rd * t, KIFS_STAGE, pc.fold, trap);
    glow += sampleColour(trap, KIFS_STAGE) * emission(d);
    t += marchStep(d, KIFS_STAGE);
    if (t > 10.0 || max(glow.r, max(glow.g, glow.b)) > 4.0) break;  // past the scene, or saturated
  }

  vec3 colour;
  if (KIFS_STAGE >= 8) {
    glow *= (1.0 - dot(uv, uv) * 0.55) * 0.9;
    colour = NAVY + acesNarkowicz(glow);
  } else {
    colour = NAVY + glow * 0.4;
  }
  if (KIFS_STAGE >= 9) {
    colour += (hash01(uvec3(up, pc.frame * 5u + pc.seed * 104729u + 1u)) - 0.5) * pc.grain;
    // Triangular dither of +-1 LSB before the 8-bit swapchain or PNG quantises the navy.
    float a = hash01(uvec3(up, pc.seed + 0x9e3779b9u));
    float b = hash01(uvec3(up, pc.seed + 0x7f4a7c15u));
    colour += (a + b - 1.0) / 255.0;
  }
  // The write-up works in display values; the target holds linear light.
  imageStore(target, pixel, vec4(srgbToLinear(colour), 1.0));
}
