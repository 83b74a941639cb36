#version 460
// The strands in the flow bake.comp baked this frame: a step takes one filtered fetch where the
// volume reaches and the exact noise beyond it; src/scenes/noodles/field_bake.h says when and why.
#extension GL_GOOGLE_include_directive : require
// The field and the integrator from the push block, not specialised (integrate_strands.glsl says why).
#define STRAND_FIELD pc.fieldKind
#define STRAND_INTEGRATOR pc.integrator
#include "noodles/integrate_strands.glsl"

layout(binding = 1) uniform sampler3D bakedFlow;  // the noise part of the flow, RGB10A2 over -bakeRange..bakeRange, linear filter

vec3 strandVelocity(vec3 p, FieldSettings field) {
  vec3 u = (p - pc.bakeOrigin) * pc.bakeInverseSpacing;  // texel units, centres at whole numbers
  if (all(greaterThanEqual(u, vec3(0.0))) && all(lessThanEqual(u, pc.bakeLastTexel))) {
    vec3 v = (textureLod(bakedFlow, (u + 0.5) / (pc.bakeLastTexel + 1.0), 0.0).xyz - 0.5) * (2.0 * pc.bakeRange);
    v.z += field.lift;
    return v;
  }
  return flowVelocity(p, field);
}
