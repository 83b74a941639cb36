// The crystal's shape and colours; mirrors src/scenes/bloom/bloom_math.h.
const float kCrystalRadius = 0.8;
const float kCoreRadius = 0.7;
const vec3 kPristine = vec3(0.86, 0.89, 0.93);
const float kCoverFrom = 0.04, kCoverTo = 0.20;
const float kGlassDensity = 0.9, kVapourDensity = 9.0;

bool insideCrystal(vec3 normalised) { return abs(normalised.x) + abs(normalised.y) + abs(normalised.z) <= 1.0; }
bool insideCore(vec3 normalised) { return abs(normalised.x) + abs(normalised.y) + abs(normalised.z) <= kCoreRadius; }

float octahedronDistance(vec3 p, float radius) { return (abs(p.x) + abs(p.y) + abs(p.z) - radius) * 0.57735027; }
uint crystalSamples(float span, float radius, uint samples) {
  const float wanted = ceil(span / (2.0 * radius) * float(samples));
  return clamp(uint(max(wanted, 1.0)), 1u, max(samples, 1u));
}

float vapourCover(float v) { return smoothstep(kCoverFrom, kCoverTo, v); }
float sampleDensity(float v) { return kGlassDensity + kVapourDensity * vapourCover(v); }
