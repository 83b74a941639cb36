#version 460
// Runs the diamond's back exit (searched, and tried on one facet) and first walk step, and every shape's
// distance, on given probes, so a test can hold the GLSL (glass/diamond.glsl, glass/shapes.glsl) to its
// C++ mirror.
#extension GL_GOOGLE_include_directive : require
#define DIAMOND_BINDING 0
#include "glass/optics.glsl"
#include "glass/probe_blocks.h"
#include "glass/shapes.glsl"

const float PROBE_ETA = 2.4175;  // diamond

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 1) readonly buffer Shapes { GlassShapeDims shapes[]; };  // at most 8
layout(std430, set = 0, binding = 2) readonly buffer Probes { GlassDiamondProbe probes[]; };
layout(std430, set = 0, binding = 3) writeonly buffer Results { GlassDiamondProbeResult results[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= probes.length()) return;
  const GlassDiamondProbe probe = probes[i];

  GlassDiamondProbeResult r;
  bool found = diamondExit(probe.origin, probe.direction, r.t, r.normal, r.facet);
  r.found = found ? 1u : 0u;
  float t;
  vec3 n;
  r.followed = found && r.facet < DIAMOND_PLANES && diamondExitThrough(probe.origin, probe.direction, r.facet, t, n) ? 1u : 0u;
  if (found && diamondExitThrough(probe.origin, probe.direction, (r.facet + 1) % DIAMOND_PLANES, t, n)) r.followed |= 2u;
  DiamondWalk walk = diamondWalkStart(probe.origin, probe.direction, 1.0, 6, NO_ROUTE);
  diamondStep(walk, PROBE_ETA, true, r.exitDir, r.exitWeight);
  for (int k = 0; k < 8; ++k) r.distances[k] = k < shapes.length() ? shapeSdf(shapes[k], probe.point) : 0.0;
  r.pad1 = 0.0;
  results[i] = r;
}
