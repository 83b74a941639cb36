#version 460
// The crystal: the ray's entry and exit found analytically (a convex polytope of 8 planes), the vapour
// integrated front to back over jittered samples, each in the colour of its own concentration (colour
// fronts move through the crystal with the vapour), and a Fresnel rim and facet shading at the entry;
// during the climax a spectral shimmer. The silhouette is antialiased from the ray's analytic chord through the
// octahedron, so a lower render scale is softer, never stair-stepped. Output is premultiplied: the
// chamber shows through what the crystal lets pass.
#extension GL_GOOGLE_include_directive : require
#include "crystal.glsl"
#include "crystal_push.h"
#include "../common/hash.glsl"
layout(location = 0) in vec3 world;
layout(location = 0) out vec4 colour;
layout(binding = 0) uniform sampler3D vapour;
layout(push_constant) uniform Push { BloomCrystalPush pc; };

const vec3 kLight = normalize(vec3(-0.4, 0.8, 0.6));

// The facet whose outward normal has these signs, over the volume's premultiplied colour and alpha:
// premultiplied colour and alpha.
vec4 shadeFacet(vec3 signs, vec3 rd, vec4 volume) {
  const vec3 normal = signs * 0.57735027;
  // A glass surface: some opacity however thin the path, so the silhouette stays crisp.
  const float fresnel = 0.02 + 0.98 * pow(1.0 - abs(dot(normal, rd)), 5.0);
  const float surface = (1.0 - volume.a) * (0.22 + 0.5 * fresnel);
  // Facets catch the light; the rim brightens towards grazing angles.
  const vec3 lit = (volume.rgb + kPristine * surface) * (0.72 + 0.38 * max(dot(normal, kLight), 0.0)) +
                   vec3(1.0, 0.99, 0.97) * fresnel * 0.55;
  return vec4(lit, volume.a + surface);
}

void main() {
  const vec3 ro = pc.eye;
  const vec3 rd = normalize(world - ro);
  // The ray's chord through the octahedron (the 8 half-spaces n . p <= R, n = (+-1, +-1, +-1)): positive
  // inside the silhouette, negative outside, zero on it, and close to linear across a pixel there.
  // Its screen-space slope turns it into the pixel's coverage; derivatives first, before any discard.
  float chordIn = -1e30, chordOut = 1e30;
  for (int k = 0; k < 8; ++k) {
    const vec3 n = vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0, (k & 4) != 0 ? 1.0 : -1.0);
    const float towards = dot(n, rd), room = kCrystalRadius - dot(n, ro);
    if (towards > 1e-6) chordOut = min(chordOut, room / towards);
    else if (towards < -1e-6) chordIn = max(chordIn, room / towards);
  }
  const float chord = chordOut - chordIn;
  const float slope = max(length(vec2(dFdx(chord), dFdy(chord))), 1e-6);
  const float coverage = clamp(0.5 + chord / slope, 0.0, 1.0);

  // The entry and the exit are the chord's ends (the eye is never inside the crystal, but a ray from
  // inside would start at the eye).
  const float t = max(chordIn, 0.0);
  const vec3 entry = ro + rd * t;
  // The entry's facet is the signs of its coordinates. Where an edge between facets (a coordinate's
  // zero) crosses the pixel, each side's share of it, as the silhouette's coverage is found.
  const vec3 positiveShare = clamp(0.5 + entry / max(fwidth(entry), vec3(1e-6)), 0.0, 1.0);
  if (coverage <= 0.0) discard;
  const float span = max(chordOut - t, 0.0);

  // Front to back, each sample in its own concentration's colour; the vapour makes it dense
  // (bloom_math.h: sampleDensity). A sample's colour counts by what it adds to the path's opacity and by
  // its pigment, the square of its concentration (vapourPigment): a thin amber rim over a saturated
  // heart tints it little, and white glass with no vapour counts only where nothing else is.
  // The samples follow the chord's length (crystalSamples): a step no longer than the longest chord's.
  // The march stops where the path is opaque (transmittance 0.005).
  const uint samples = crystalSamples(span, kCrystalRadius, pc.samples);
  const float step = span / float(samples);
  const float jitter = hash01(uvec3(uvec2(gl_FragCoord.xy), pc.seed ^ (pc.frame * 747796405u)));
  float transmit = 1.0;
  vec4 tinted = vec4(kPristine, 1.0) * 1e-6;  // colour x weight, weight
  if (pc.clearGlass != 0u) {
    // Clear glass (no vapour anywhere past kCoverFrom, the state the crystal rests in): every sample is
    // the glass's density and colour, so the path is known without sampling the lattice.
    transmit = exp(-kGlassDensity * span);
  }
  for (uint i = 0u; pc.clearGlass == 0u && i < samples && transmit > 0.005; ++i) {
    const vec3 p = entry + rd * ((float(i) + jitter) * step);
    const float v = textureLod(vapour, p / kCrystalRadius * 0.5 + 0.5, 0.0).r;
    const float a = 1.0 - exp(-sampleDensity(v) * step);
    tinted += vec4(vapourColour(v, pc.thresholds), 1.0) * (transmit * a * vapourPigment(v));
    transmit *= 1.0 - a;
  }
  const vec4 volume = vec4(tinted.rgb / tinted.a * (1.0 - transmit), 1.0 - transmit);  // premultiplied
  // The facet the pixel sees, shaded; where an edge between facets crosses it, each facet weighted by
  // its share: a hard switch there, between facets shaded differently, showed as stair-steps.
  vec4 shaded;  // premultiplied colour, alpha
  if (all(equal(positiveShare, round(positiveShare)))) {
    shaded = shadeFacet(positiveShare * 2.0 - 1.0, rd, volume);
  } else {
    shaded = vec4(0.0);
    for (int k = 0; k < 8; ++k) {
      const vec3 signs = vec3((k & 1) != 0 ? 1.0 : -1.0, (k & 2) != 0 ? 1.0 : -1.0, (k & 4) != 0 ? 1.0 : -1.0);
      const vec3 shares = mix(1.0 - positiveShare, positiveShare, greaterThan(signs, vec3(0.0)));
      const float share = shares.x * shares.y * shares.z;
      if (share > 0.0) shaded += share * shadeFacet(signs, rd, volume);
    }
  }
  vec3 sum = shaded.rgb;
  const float alpha = shaded.a;

  if (pc.shimmer > 0.0) {  // the chamber sings: a slow spectral wash across the crystal
    const vec2 uv = gl_FragCoord.xy * 0.004;
    const vec3 spectrum = 0.5 + 0.5 * cos(6.2831853 * (vec3(0.0, 0.33, 0.67) + pc.time * 0.35 + uv.x + uv.y));
    sum = mix(sum, sum * (0.6 + 0.8 * spectrum), pc.shimmer * 0.35);
  }
  colour = vec4(sum, alpha) * coverage;
}
