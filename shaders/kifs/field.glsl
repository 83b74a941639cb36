// The KIFS distance field at each teaching stage; mirrors src/scenes/kifs/kifs_math.h.
#ifndef KIFS_FIELD_GLSL
#define KIFS_FIELD_GLSL

const vec3 RAYS = vec3(0.5, 0.4, 0.6);
const vec3 CYLINDERS = vec3(0.11, 0.09, 0.13);  // stages 3-5, world space
const vec3 FOLD = vec3(1.0, 0.8, 1.2);
const vec3 PLANE_ROTATIONS = vec3(0.62, 0.38, 0.91);
const float SCALE_MULT = 1.7;
const float SCALE_ACCUM = 1.7;
const float WARP_FREQ = 56.3;
const float WARP_AMP = 0.29;
const float CORE_RADIUS = 0.44;

vec2 rotate(vec2 v, float a) {
  float c = cos(a), s = sin(a);
  return vec2(c * v.x - s * v.y, s * v.x + c * v.y);
}

float smin(float a, float b, float k) {
  float h = clamp(0.5 + 0.5 * (b - a) / k, 0.0, 1.0);
  return mix(b, a, h) - k * h * (1.0 - h);
}

// The slow tumble plus drag. Linear, so the march applies it to the ray once, not to every sample.
vec3 tumble(vec3 p, int step, vec2 angles) {
  if (step <= 2) return p;  // the sphere stages sit still
  p.xz = rotate(p.xz, angles.x);
  p.xy = rotate(p.xy, angles.y);
  return p;
}

// The field at a point already in the tumbled frame.
// `fold` scales the asymmetric fold's offsets (1: the write-up's; live input breathes it with the bass).
float field(vec3 p, int step, float fold, out vec3 trap) {
  if (step <= 2) {
    trap = abs(p);
    return length(p) - 0.5;
  }
  if (step <= 5) {
    vec3 q = p;
    if (step == 5) q += sin(q.zxy * WARP_FREQ) * WARP_AMP;
    float raysX = length(q.yz) - CYLINDERS.x;
    float raysY = length(q.xz) - CYLINDERS.y;
    float raysZ = length(q.xy) - CYLINDERS.z;
    trap = abs(q);
    return step == 3 ? min(raysX, min(raysY, raysZ)) : smin(smin(raysX, raysY, 0.3), raysZ, 0.3);
  }

  vec3 q = p + sin(p.zxy * WARP_FREQ) * WARP_AMP;
  q = abs(q) - FOLD * fold;
  q.xy = rotate(q.xy, PLANE_ROTATIONS.x);
  q.xz = rotate(q.xz, PLANE_ROTATIONS.y);
  q.yz = rotate(q.yz, PLANE_ROTATIONS.z);
  q *= SCALE_MULT;
  float scale = 0.26 * SCALE_ACCUM;
  trap = abs(q);

  float raysX = length(q.yz) - RAYS.x;
  float raysY = length(q.xz) - RAYS.y;
  float raysZ = length(q.xy) - RAYS.z;
  const float k = 0.1;
  float h1 = clamp(6.7 + 0.1 * (raysX - raysY) / k, 0.1, 0.4);
  float merged = mix(raysX, raysY, h1) - k * h1 * (1.0 - h1);
  float h2 = clamp(0.1 + 0.1 * (merged - raysZ) / k, 0.0, 0.8);
  merged = mix(merged, raysZ, h2) - k * h2 * (-7.3 - h2);
  merged /= scale;

  float core = length(p) - CORE_RADIUS;
  float h3 = clamp(0.5 + 0.5 * (core - merged) / 0.3, 0.0, 1.0);
  return (mix(core, merged, h3) - 0.3 * h3 * (1.0 - h3)) * 0.3;
}

float marchStep(float d, int step) { return step == 1 ? abs(d) + 0.015 : abs(d) * 0.45 + 0.015; }
float emission(float d) { return 0.0035 / (abs(d) + 0.005); }

const vec3 COL_HOT = vec3(1.0, 0.84, 0.42);
const vec3 COL_AMBER = vec3(0.961, 0.620, 0.043);
const vec3 COL_EMBER = vec3(0.45, 0.10, 0.03);

// Amber, and from stage 7 the orbit trap's gold core and rust recesses.
vec3 sampleColour(vec3 trap, int step) {
  if (step < 7) return COL_AMBER;
  vec3 colour = mix(COL_HOT, COL_AMBER, smoothstep(0.0, 1.0, trap.x));
  return mix(colour, COL_EMBER, smoothstep(0.0, 1.0, trap.y));
}

#endif
