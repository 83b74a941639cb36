#version 460
// One whole chain per instance, drawn as a tube impostor: a ribbon through the chain's particles
// that always faces the eye (two vertices a particle, one triangle strip), closed at both ends by a
// round cap (two more vertices each, a radius past the end), shaded in the fragment shader as the
// glowing cylinder it stands for. The radius is the same along the whole tube and through its life
// (the gas dims, the glass stays), but never below F.minTubeRadiusPixels (drawnTubeRadius in
// src/scenes/neon/tube_light.h): a far tube on a small frame stays a continuous line instead of a
// ribbon thinner than a pixel.
#extension GL_GOOGLE_include_directive : require
#include "neon/camera.glsl"
#include "neon/head_state.h"

layout(std430, set = 0, binding = 1) readonly buffer Particles { vec4 particles[]; };  // xyz, w life
layout(std430, set = 0, binding = 3) readonly buffer Heads { NeonHeadState heads[]; };  // for the release's serial
layout(location = 0) out float across;      // -1..1 over the ribbon
layout(location = 1) flat out uint colour;  // which of the three neon colours
layout(location = 2) out float cap;         // 0 along the tube, out to 1 at the far edge of an end cap
layout(location = 3) out float fade;        // the gas' brightness through its life
layout(location = 4) out float rim;         // the antialiased rim's width, in units of across

// Which neon colour the release with this serial glows in: tubeColour in src/scenes/neon/tube_light.h.
uint tubeColour(uint serial) { return (serial + serial / 3u) % 3u; }

void main() {
  const uint chain = gl_InstanceIndex, perChain = F.particlesPerChain;
  // Vertex pairs: 0 the head's cap, 1..perChain the particles (head first), perChain + 1 the tail's cap.
  const uint pair = gl_VertexIndex / 2;
  const uint k = clamp(pair, 1u, perChain) - 1u;
  const uint base = chain * perChain;
  const vec4 p = particles[base + k];
  const float life = clamp(p.w, 0.0, 1.0);
  fade = smoothstep(0.0, NEON_FADE_LIFE, life);
  float radius = F.tubeRadius;
  const float depth = max((F.viewProjection * vec4(p.xyz, 1.0)).w, 1e-3);  // distance along the view
  const float pixels = radius * F.focalPixels / depth;
  const float widen = max(1.0, F.minTubeRadiusPixels / max(pixels, 1e-6));
  radius = life > 0.0 ? radius * widen : 0.0;
  // The ribbon's direction, measured over at least the tube's width. Where a chain is gathered (a
  // young tube's tail, still at its origin) neighbouring particles are a rounding error apart, and a
  // side vector from their difference points anywhere: a twisted sliver, a different one on every
  // GPU (the H200's neon goldens, docs/RELIABILITY.md). So look toward the head until the chain has
  // left the tube's own width.
  const vec3 behind = particles[base + min(k + 1, perChain - 1)].xyz;
  vec3 ahead = particles[base + (k == 0 ? 0 : k - 1)].xyz;
  for (uint j = k; j > 1 && distance(ahead, behind) < 2.0 * radius; --j) ahead = particles[base + j - 2].xyz;
  const vec3 tangent = ahead - behind;
  const vec3 view = normalize(F.eye - p.xyz);
  const vec3 side = cross(tangent, view);
  const float sideLength = length(side);  // 0 only for a tube pointing straight at the eye
  // A chain gathered within its own width is a point, not yet a tube: it grows in as it leaves.
  radius *= clamp(length(tangent) / max(2.0 * radius, 1e-6), 0.0, 1.0);
  across = (gl_VertexIndex & 1) == 0 ? -1.0 : 1.0;
  rim = 1.5 / max(pixels * widen, 1e-3);  // a pixel and a half, in units of `across`
  colour = tubeColour(heads[chain].serial);  // consecutive releases never share a colour
  vec3 offset = sideLength > 0.0 ? side / sideLength * across * radius : vec3(0.0);
  // The caps reach a radius past the ends, along the tube as seen (its direction across the view).
  cap = pair == 0u || pair == perChain + 1u ? 1.0 : 0.0;
  const vec3 onward = sideLength > 0.0 ? normalize(cross(view, side)) : vec3(0.0);  // toward the head
  offset += onward * (pair == 0u ? radius : pair == perChain + 1u ? -radius : 0.0);
  gl_Position = F.viewProjection * vec4(p.xyz + offset, 1.0);
}
