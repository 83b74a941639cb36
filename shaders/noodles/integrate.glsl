// Euler and RK4 steps along the flow; mirrors src/scenes/noodles/integrate.h.
#ifndef NOODLES_INTEGRATE_GLSL
#define NOODLES_INTEGRATE_GLSL
#include "common/flow_field.glsl"

// The flow a strand follows: the exact field (integrate.comp) or its baked volume (integrate_baked.comp).
vec3 strandVelocity(vec3 p, FieldSettings field);

const uint INTEGRATOR_EULER = 0u;
const uint INTEGRATOR_RK4 = 1u;
const uint TANGENT_NORMALIZED = 0u;
const uint TANGENT_RAW = 1u;
const float STILL_SPEED_SQUARED = 1e-20;

vec3 directionOf(vec3 v, vec3 fallback) {
  float speedSquared = dot(v, v);
  return speedSquared > STILL_SPEED_SQUARED ? v / sqrt(speedSquared) : fallback;
}

vec3 travel(vec3 v, uint mode) {
  if (mode == TANGENT_RAW) return v;
  float speedSquared = dot(v, v);
  return speedSquared > STILL_SPEED_SQUARED ? v / sqrt(speedSquared) : vec3(0.0);
}

// k1 = travel(flowVelocity(p)), already evaluated by the caller for the frame at p.
vec3 advance(vec3 p, vec3 k1, float h, uint integrator, uint mode, FieldSettings field) {
  if (integrator == INTEGRATOR_EULER) return p + k1 * h;
  vec3 k2 = travel(strandVelocity(p + k1 * (0.5 * h), field), mode);
  vec3 k3 = travel(strandVelocity(p + k2 * (0.5 * h), field), mode);
  vec3 k4 = travel(strandVelocity(p + k3 * h, field), mode);
  return p + (k1 + (k2 + k3) * 2.0 + k4) * (h / 6.0);
}

#endif
