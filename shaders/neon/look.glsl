// The neon look's small curves, shared by the compute passes; mirrors src/scenes/neon/look.h, whose
// unit tests pin them down.
#ifndef NEON_LOOK_GLSL
#define NEON_LOOK_GLSL

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
// equal numbers of taps in equal areas, the golden angle spreads them evenly around. A pass walks the
// spiral: each tap's direction is the one before turned by the golden angle, one complex product,
// rather than a cos and a sin a tap (look.h's spiralTap is the same spiral, taken tap by tap).
const vec2 kGoldenTurn = vec2(-0.737368822, 0.675490379);  // (cos, sin) of pi * (3 - sqrt(5)), look.h's kGoldenAngle
float spiralRadius(uint i, uint n) { return sqrt((float(i) + 0.5) / float(n)); }
vec2 nextHeading(vec2 heading) {
  return vec2(heading.x * kGoldenTurn.x - heading.y * kGoldenTurn.y, heading.x * kGoldenTurn.y + heading.y * kGoldenTurn.x);
}

#endif
