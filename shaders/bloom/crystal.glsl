// The crystal's shape and colours; mirrors src/scenes/bloom/bloom_math.h.
const float kCrystalRadius = 0.8;
const vec3 kPristine = vec3(0.86, 0.89, 0.93);
const vec3 kAmber = vec3(1.00, 0.50, 0.06);
const vec3 kRose = vec3(0.90, 0.24, 0.36);
const vec3 kCrimson = vec3(0.50, 0.015, 0.05);
const float kColourWidth = 0.06;

bool insideCrystal(vec3 normalised) { return abs(normalised.x) + abs(normalised.y) + abs(normalised.z) <= 1.0; }

float octahedronDistance(vec3 p, float radius) { return (abs(p.x) + abs(p.y) + abs(p.z) - radius) * 0.57735027; }

vec3 phaseColour(float v) {
  vec3 c = kPristine;
  c = mix(c, kAmber, smoothstep(0.20 - kColourWidth * 0.5, 0.20 + kColourWidth * 0.5, v));
  c = mix(c, kRose, smoothstep(0.40 - kColourWidth * 0.5, 0.40 + kColourWidth * 0.5, v));
  c = mix(c, kCrimson, smoothstep(0.60 - kColourWidth * 0.5, 0.60 + kColourWidth * 0.5, v));
  return c;
}
