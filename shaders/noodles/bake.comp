#version 460
// One invocation a texel: the noise part of the flow (curl or bitangent, no lift: the integrate pass
// adds it) at the texel's centre, for integrate_baked.comp to sample; src/scenes/noodles/strand.h's
// bakeField is the CPU reference and field_bake.h's bakedTexel the packing.
//
// A texel's three noises need 24 hashed lattice gradients, two thirds of its arithmetic, yet a
// workgroup's texels (under one noise unit across at the planned spacing) share a few dozen lattice
// points: the workgroup hashes each of them once into shared memory and every texel blends from there.
// Where a coarsened bake spans more of the lattice than the table holds, the workgroup evaluates the
// field texel by texel as before; both give the same field.
#extension GL_GOOGLE_include_directive : require
#include "common/flow_field.glsl"
#include "noodles/integrate_push.h"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 4) in;
// The volume's A2B10G10R10 words through a 32-bit view: the shader rounds (field_bake.h says why).
layout(binding = 0, r32ui) uniform writeonly uimage3D bakedFlow;

layout(push_constant) uniform Push { NoodlesBakePush pc; };
// The field (curl or bitangent) specialises the pipeline, as in integrate_strands.glsl.
layout(constant_id = 0) const uint BAKE_FIELD = FIELD_CURL;

const int SPAN = 4;                     // lattice points the table holds along each axis, per noise
const int SPAN_POINTS = SPAN * SPAN * SPAN;
shared vec3 lattice[3 * SPAN_POINTS];   // the three potentials' gradients (the bitangent's x unused)

// Where a texel falls in potential `which`'s noise: q, q + offsetY, q + offsetZ as flowVelocity has them.
vec3 noisePoint(ivec3 texel, int which) {
  vec3 q = (pc.origin + vec3(texel) * pc.spacing) * pc.noiseScale;
  return which == 0 ? q : q + (which == 1 ? pc.offsetY : pc.offsetZ);
}

vec3 sharedGradient(vec3 x, int which, ivec3 first) {
  // Clamped to the table: should this texel's arithmetic round x an ulp across a cell boundary from
  // where the workgroup's corners saw it, the neighbouring cell gives the same noise there (it is C1).
  const ivec3 c = clamp(ivec3(floor(x)) - first, ivec3(0), ivec3(SPAN - 2));
  const int i = which * SPAN_POINTS + (c.z * SPAN + c.y) * SPAN + c.x;
  const int Y = SPAN, Z = SPAN * SPAN;
  return noiseFromCorners(x - vec3(first + c), lattice[i], lattice[i + 1], lattice[i + Y], lattice[i + Y + 1],
                          lattice[i + Z], lattice[i + Z + 1], lattice[i + Z + Y], lattice[i + Z + Y + 1])
      .gradient;
}

void main() {
  const ivec3 texel = ivec3(gl_GlobalInvocationID);
  const ivec3 groupFirst = ivec3(gl_WorkGroupID * gl_WorkGroupSize);
  const ivec3 groupLast = groupFirst + ivec3(gl_WorkGroupSize) - 1;
  // Each potential's lattice corner range over the workgroup (a point's cell grows with its texel).
  ivec3 first[3];
  bool fits = true;
  for (int which = BAKE_FIELD == FIELD_CURL ? 0 : 1; which < 3; ++which) {
    first[which] = ivec3(floor(noisePoint(groupFirst, which)));
    const ivec3 span = ivec3(floor(noisePoint(groupLast, which))) - first[which] + 2;
    fits = fits && all(lessThanEqual(span, ivec3(SPAN)));
  }
  if (fits) {  // uniform across the workgroup
    const int invocations = int(gl_WorkGroupSize.x * gl_WorkGroupSize.y * gl_WorkGroupSize.z);
    for (int k = int(gl_LocalInvocationIndex); k < 3 * SPAN_POINTS; k += invocations) {
      const int which = k / SPAN_POINTS, j = k % SPAN_POINTS;
      if (BAKE_FIELD != FIELD_CURL && which == 0) continue;
      const ivec3 point = first[which] + ivec3(j % SPAN, (j / SPAN) % SPAN, j / (SPAN * SPAN));
      lattice[k] = latticeGradient(latticeCell(vec3(point)));
    }
    barrier();
  }
  if (any(greaterThanEqual(texel, imageSize(bakedFlow)))) return;

  vec3 v;
  if (fits) {
    const vec3 gy = sharedGradient(noisePoint(texel, 1), 1, first[1]);
    const vec3 gz = sharedGradient(noisePoint(texel, 2), 2, first[2]);
    v = BAKE_FIELD == FIELD_CURL ? curlOf(sharedGradient(noisePoint(texel, 0), 0, first[0]), gy, gz) : bitangentOf(gy, gz);
  } else {
    FieldSettings field = FieldSettings(BAKE_FIELD, pc.noiseScale, pc.offsetY, pc.offsetZ, 0.0);
    v = flowVelocity(pc.origin + vec3(texel) * pc.spacing, field);
  }
  // precise: a fused multiply-add here would round some texels a step away from another driver's.
  precise const vec3 unit = clamp(v / (2.0 * pc.range) + 0.5, 0.0, 1.0);
  precise const uvec3 level = uvec3(floor(unit * 1023.0 + 0.5));
  imageStore(bakedFlow, texel, uvec4(level.x | level.y << 10 | level.z << 20, 0u, 0u, 0u));
}
