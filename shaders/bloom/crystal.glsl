// The crystal's shape and colours; mirrors src/scenes/bloom/bloom_math.h.
const float kCrystalRadius = 0.8;
const float kCoreRadius = 0.7;
const vec3 kPristine = vec3(0.86, 0.89, 0.93);
const vec3 kAmber = vec3(0.955, 0.40, 0.021);
const vec3 kRose = vec3(0.84, 0.155, 0.30);
const vec3 kCrimson = vec3(0.30, 0.0025, 0.017);
const float kColourEdge = 0.06, kColourLead = 0.05;
const float kGlassPigment = 0.01;
const float kCoverFrom = 0.04;
const float kGlassDensity = 0.9, kVapourDensity = 18.0;

bool insideCrystal(vec3 normalised) { return abs(normalised.x) + abs(normalised.y) + abs(normalised.z) <= 1.0; }
bool insideCore(vec3 normalised) { return abs(normalised.x) + abs(normalised.y) + abs(normalised.z) <= kCoreRadius; }

// Voxel i's centre in the lattice's normalised cube [-1, 1]^3 (bloom_math.h: voxelCentre).
vec3 voxelCentre(ivec3 voxel, int n) { return (vec3(voxel) + 0.5) / float(n) * 2.0 - 1.0; }

// Voxel p's place in an n^3 lattice buffer: x fastest, then y, then z, an image's texel order (so a
// checkpoint's bytes read the same either way).
uint latticeIndex(ivec3 p, int n) { return uint((p.z * n + p.y) * n + p.x); }

// The voxels [first, end) along z that one invocation of an n^3 pass walks: its run `run` of `length`
// voxels up column xy, clipped to where the column crosses the crystal (|z| <= 1 - |x| - |y|),
// widened a voxel each way so that rounding never drops one; callers still test each voxel with
// insideCrystal. Empty (first >= end) for a run, or a whole column, outside.
ivec2 crystalColumnRun(ivec2 xy, int n, int run, int length) {
  const vec3 centre = voxelCentre(ivec3(xy, 0), n);
  const float halfHeight = 1.0 - abs(centre.x) - abs(centre.y);
  if (halfHeight < -2.0 / float(n)) return ivec2(0);
  return ivec2(max(run * length, int(floor((1.0 - halfHeight) * 0.5 * float(n))) - 1),
               min(min((run + 1) * length, n), int(ceil((1.0 + halfHeight) * 0.5 * float(n))) + 1));
}

uint crystalSamples(float span, float radius, uint samples) {
  const float wanted = ceil(span / (2.0 * radius) * float(samples));
  return clamp(uint(max(wanted, 1.0)), 1u, max(samples, 1u));
}

// A sample's colour from its own concentration; `thresholds` are amber's, rose's and crimson's.
vec3 vapourColour(float v, vec3 thresholds) {
  const vec3 at = thresholds - kColourLead;
  vec3 c = mix(kPristine, kAmber, smoothstep(at.x - 0.5 * kColourEdge, at.x + 0.5 * kColourEdge, v));
  c = mix(c, kRose, smoothstep(at.y - 0.5 * kColourEdge, at.y + 0.5 * kColourEdge, v));
  return mix(c, kCrimson, smoothstep(at.z - 0.5 * kColourEdge, at.z + 0.5 * kColourEdge, v));
}

float vapourPigment(float v) { return kGlassPigment + v * v; }
float sampleDensity(float v) { return kGlassDensity + kVapourDensity * v * v; }
