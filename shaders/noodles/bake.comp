#version 460
// One invocation a texel: the noise part of the flow (curl or bitangent, no lift: the integrate pass
// adds it) at the texel's centre, for integrate_baked.comp to sample; src/scenes/noodles/strand.h's
// bakeField is the CPU reference.
#extension GL_GOOGLE_include_directive : require
#include "common/flow_field.glsl"
#include "noodles/integrate_push.h"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = 0, rgb10_a2) uniform writeonly image3D bakedFlow;

layout(push_constant) uniform Push { NoodlesBakePush pc; };
// The field (curl or bitangent) specialises the pipeline, as in integrate_strands.glsl.
layout(constant_id = 0) const uint BAKE_FIELD = FIELD_CURL;

void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(texel, imageSize(bakedFlow)))) return;
  FieldSettings field = FieldSettings(BAKE_FIELD, pc.noiseScale, pc.offsetY, pc.offsetZ, 0.0);
  vec3 v = flowVelocity(pc.origin + vec3(texel) * pc.spacing, field);
  imageStore(bakedFlow, texel, vec4(clamp(v / (2.0 * pc.range) + 0.5, 0.0, 1.0), 0.0));
}
