#version 460
// The neon scene's last pass: scene colour (the depth-of-field output) with chromatic aberration, the
// bloom, the ground's mirror reflection, the seed's noise tint blended by linear burn, a vignette, the
// ACES fit, then film grain. Every effect has a bit in `flags`, so the lead's stage switch (and any
// debugging) turns effects off without another shader. Writes linear light for the host's present pass.
// Its push block and flags are neon/composite_push.h.
#extension GL_GOOGLE_include_directive : require
#include "common/color.glsl"
#include "common/hash.glsl"
#include "common/noise.glsl"
#include "neon/bloom.glsl"
#include "neon/composite_push.h"
#include "neon/look.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform sampler2D scene;                    // linear HDR; linear, clamp to edge
layout(set = 0, binding = 1) uniform sampler2D bloom;                    // up chain level 1; linear, clamp
layout(set = 0, binding = 2, rgba16f) uniform writeonly image2D target;  // tone-mapped linear light
layout(push_constant) uniform Push { NeonCompositePush pc; };

bool on(uint flag) { return (pc.flags & flag) != 0u; }

// The ground seen from a level camera at height h: a ground point whose pixel lies `below` pixels
// under the horizon is about size.y / below heights away, and sideways by dx / below heights. Ripples
// laid out in those coordinates shrink into the distance as water does; but near the line they would
// shrink below a pixel a row and tear the reflection into jagged rows, so the distance is capped at
// about ten camera heights (a tenth of the frame below the line) and the ripples stop shrinking there.
vec2 rippleSlope(vec2 pixel, vec2 size, float below) {
  const float far = below + 0.1 * size.y;
  const vec2 ground = vec2(pixel.x - 0.5 * size.x, size.y) / far;
  return gradientNoise(vec3(ground, pc.time * 0.25)).gradient.xy;
}

vec3 reflection(vec2 pixel, vec2 size) {
  const float below = pixel.y - pc.horizonY;
  if (below <= 0.0) return vec3(0.0);
  // Scaled by the distance below the line: distant ripples are small on screen and move little.
  const vec2 offset = rippleSlope(pixel, size, below) * pc.mirrorDistortion * (below / size.y);
  const vec2 mirrored = vec2(pixel.x, mirrorY(pixel.y, pc.horizonY)) + offset;
  // Fades with distance from the line, and before the lookup leaves the top of the frame, where a
  // clamped sampler would smear the top row.
  const float fade = (1.0 - smoothstep(0.0, pc.mirrorFade, below)) * smoothstep(0.0, 0.05 * size.y, mirrored.y);
  const vec2 uv = mirrored / size;
  vec3 c = textureLod(scene, uv, 0.0).rgb;
  if (on(NEON_COMPOSITE_BLOOM)) c += pc.bloomStrength * textureLod(bloom, uv, pc.bloomLod).rgb;
  return c * (pc.mirrorStrength * fade);
}

void main() {
  const ivec2 size = imageSize(target);
  const ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, size))) return;
  const vec2 sizeF = vec2(size);
  const vec2 pixel = vec2(p) + 0.5;
  const vec2 uv = pixel / sizeF;

  vec3 c;
  if (on(NEON_COMPOSITE_ABERRATION)) {  // a lens' lateral colour: red lands a little outward, blue a little inward
    const vec2 shift = (uv - 0.5) * pc.aberration;
    c = vec3(textureLod(scene, uv + shift, 0.0).r, textureLod(scene, uv, 0.0).g, textureLod(scene, uv - shift, 0.0).b);
  } else {
    c = textureLod(scene, uv, 0.0).rgb;
  }
  if (on(NEON_COMPOSITE_BLOOM)) c += pc.bloomStrength * upsampleTent(bloom, uv, 1.0 / sizeF, pc.bloomLod);
  if (on(NEON_COMPOSITE_MIRROR)) c += reflection(pixel, sizeF);

  if (on(NEON_COMPOSITE_TINT)) {  // the seed's colour mask: slow noise picks between the two colours
    // (the noise rarely leaves +-0.5, so +-0.35 spans the colours and still reaches each of them)
    const vec2 q = pixel / sizeF.y * 1.5 + pc.time * 0.05;
    const float n = smoothstep(-0.35, 0.35, gradientNoise(vec3(q, pc.time * 0.02)).value);
    // The seed burned display values; in linear light the same subtraction would crush every shadow,
    // so the burn works on square roots (close to a display encoding) and squares back.
    const vec3 mask = sqrt(mix(pc.tintColour0, pc.tintColour1, n));
    const vec3 burned = linearBurn(sqrt(c), mask);
    c = mix(c, burned * burned, pc.tintStrength);
  }
  if (on(NEON_COMPOSITE_VIGNETTE)) c *= vignette(length(pixel - 0.5 * sizeF) / length(0.5 * sizeF), pc.vignette);

  c = acesNarkowicz(c);
  // Grain after the tone map, or the curve's toe would crush it in the shadows; added in a square-root
  // encoding (near perceptual) so it reads evenly from shadows to highlights.
  if (on(NEON_COMPOSITE_GRAIN)) {
    const float g = (hash01(uvec3(p, pc.frame * 3u + 0x5bd1e995u)) - 0.5) * pc.grain;
    const vec3 s = max(sqrt(c) + g, 0.0);
    c = s * s;
  }
  imageStore(target, p, vec4(c, 1.0));
}
