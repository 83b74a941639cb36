// The body of integrate.comp and integrate_baked.comp, which define strandVelocity. One invocation
// per strand: start on the seed grid, follow the flow for `segments` steps and write a node
// (position + frame) at the start and after every step; src/scenes/noodles/strand.h is the CPU
// reference for exactly this. Dispatched once per chunk of strands (see strand_layout.h).
#ifndef NOODLES_INTEGRATE_STRANDS_GLSL
#define NOODLES_INTEGRATE_STRANDS_GLSL
#include "noodles/integrate.glsl"
#include "noodles/packing.glsl"
#include "noodles/integrate_push.h"

layout(local_size_x = 64) in;
layout(binding = 0, std430) writeonly buffer Nodes { uvec4 nodes[]; };  // this chunk's nodes

layout(push_constant) uniform Push { NoodlesIntegratePush pc; };

// The options that choose whole paths are specialization constants (integrate_pass.cpp builds a
// pipeline per combination when it is first used), so a pipeline carries only its own path: llvmpipe
// pays for the paths a uniform branch does not take (the exact pass 17.9 -> 6.0 ms there, most of it
// RK4's). The baked pass takes its field and integrator from the push block instead
// (integrate_baked.comp defines STRAND_FIELD and STRAND_INTEGRATOR): specialised, they made the H200's
// baked pass slower at 10^8 segments, the field RK4's by a third and the integrator Euler's by 7 %
// (docs/PERFORMANCE.md).
layout(constant_id = 0) const uint INTEGRATE_FIELD = FIELD_CURL;
layout(constant_id = 1) const uint INTEGRATE_STEP = INTEGRATOR_EULER;
layout(constant_id = 2) const uint INTEGRATE_TANGENT = TANGENT_RAW;
layout(constant_id = 3) const uint INTEGRATE_FRAMES = FRAMES_RMF;
#ifndef STRAND_FIELD
#define STRAND_FIELD INTEGRATE_FIELD
#define STRAND_INTEGRATOR INTEGRATE_STEP
#endif

vec3 strandStart(uint strand) {
  uvec3 index = uvec3(strand % pc.grid.x, (strand / pc.grid.x) % pc.grid.y, strand / (pc.grid.x * pc.grid.y));
  return (vec3(index) - (vec3(pc.grid) - 1.0) * 0.5) * pc.spacing;
}

void main() {
  uint local = gl_GlobalInvocationID.y * pc.invocationsPerRow + gl_GlobalInvocationID.x;
  if (local >= pc.chunkStrands) return;
  FieldSettings field = FieldSettings(STRAND_FIELD, pc.noiseScale, pc.offsetY, pc.offsetZ, pc.lift);

  vec3 p = strandStart(pc.firstStrand + local);
  vec3 v = strandVelocity(p, field);
  Frame frame = upVectorFrame(directionOf(v, WORLD_UP));
  nodes[nodeSlot(pc.chunkStrands, pc.segmentsPerStrand + 1u, local, 0u)] = packNode(p, frame);
  for (uint k = 1u; k <= pc.segmentsPerStrand; ++k) {
    vec3 next = advance(p, travel(v, INTEGRATE_TANGENT), pc.step, STRAND_INTEGRATOR, INTEGRATE_TANGENT, field);
    v = strandVelocity(next, field);
    vec3 tangent = directionOf(v, frame.tangent);
    frame = INTEGRATE_FRAMES == FRAMES_UP ? upVectorFrame(tangent) : transportFrame(frame, p, next, tangent);
    p = next;
    nodes[nodeSlot(pc.chunkStrands, pc.segmentsPerStrand + 1u, local, k)] = packNode(p, frame);
  }
}

#endif
