// The neon look's small curves, shared by the compute passes; mirrors src/scenes/neon/look.h, whose
// unit tests pin them down.
#ifndef NEON_LOOK_GLSL
#define NEON_LOOK_GLSL

const float kGoldenAngle = 2.39996323;  // pi * (3 - sqrt(5)): successive taps never line up

// The seed's colour mask: darkens by how far `blend` is from white; white leaves `base` alone.
vec3 linearBurn(vec3 base, vec3 blend) { return max(base + blend - 1.0, vec3(0.0)); }

// Signed circle of confusion in pixels, straight from a reverse-Z infinite-far depth value
// (linear depth = near / depth): aperture * (1 - focal / linearDepth). Negative in front of the focal
// plane, positive behind it, zero on it; the sky (depth 0) gets `aperture`, the limit at infinity.
// Written in depth rather than linear depth so the sky needs no division by zero.
float circleOfConfusion(float depth, float near, float focal, float aperture, float maxRadius) {
  return clamp(aperture * (1.0 - focal * depth / near), -maxRadius, maxRadius);
}

// Darkening towards the corners: 1 within 0.3 of the centre, easing to 1 - strength at the corners.
// `r` is the distance from the frame's centre over the distance to a corner (0 centre, 1 corner), so
// the curve is round whatever the aspect: the side edges of a 16:9 frame sit at 0.87, top and bottom at 0.49.
float vignette(float r, float strength) { return 1.0 - strength * smoothstep(0.3, 1.0, r); }

// The ground's reflection looks up the pixel mirrored about the horizon line (pixels, y down).
float mirrorY(float y, float horizonY) { return 2.0 * horizonY - y; }

// Tap i of n on a golden-angle (Vogel) spiral filling the unit disc: radius sqrt((i + 0.5) / n) puts
// equal numbers of taps in equal areas, the golden angle spreads them evenly around.
vec2 spiralTap(uint i, uint n) {
  const float r = sqrt((float(i) + 0.5) / float(n));
  const float a = float(i) * kGoldenAngle;
  return r * vec2(cos(a), sin(a));
}

#endif
