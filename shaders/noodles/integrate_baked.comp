#version 460
// The strands in the flow bake.comp baked this frame: a step takes one trilinear sample where the
// volume reaches and the exact noise beyond it; src/scenes/noodles/field_bake.h says when and why.
#extension GL_GOOGLE_include_directive : require
// The field and the integrator from the push block, not specialised (integrate_strands.glsl says why).
#define STRAND_FIELD pc.fieldKind
#define STRAND_INTEGRATOR pc.integrator
#include "noodles/integrate_strands.glsl"

layout(binding = 1) uniform sampler3D bakedFlow;  // the noise part of the flow, RGB10A2 over -bakeRange..bakeRange

// The trilinear sample with float weights, as sampleBake (field_bake.h) takes it and says why. The
// eight fetches are independent, issued together: at 10^8 segments the pass costs what one filtered
// fetch did (docs/PERFORMANCE.md, noodles).
vec3 bakedSample(vec3 u) {
  const ivec3 last = ivec3(pc.bakeLastTexel);
  const ivec3 base = min(ivec3(floor(u)), max(last, ivec3(1)) - 1);
  const vec3 f = u - vec3(base);
  vec3 sum = vec3(0.0);
  for (int corner = 0; corner < 8; ++corner) {
    const ivec3 o = ivec3(corner & 1, (corner >> 1) & 1, corner >> 2);
    const vec3 w = mix(1.0 - f, f, vec3(o));
    sum += w.x * w.y * w.z * texelFetch(bakedFlow, min(base + o, last), 0).xyz;
  }
  return sum;
}

vec3 strandVelocity(vec3 p, FieldSettings field) {
  vec3 u = (p - pc.bakeOrigin) * pc.bakeInverseSpacing;  // texel units, centres at whole numbers
  if (all(greaterThanEqual(u, vec3(0.0))) && all(lessThanEqual(u, pc.bakeLastTexel))) {
    vec3 v = (bakedSample(u) - 0.5) * (2.0 * pc.bakeRange);
    v.z += field.lift;
    return v;
  }
  return flowVelocity(p, field);
}
