#version 460
// Runs the diamond's back exit and first walk step, and every shape's distance, on given probes, so a test can
// hold the GLSL (glass/diamond.glsl, glass/shapes.glsl) to its C++ mirror.
#extension GL_GOOGLE_include_directive : require
#define DIAMOND_BINDING 0
#include "glass/optics.glsl"
#include "glass/shapes.glsl"

const float PROBE_ETA = 2.4175;  // diamond
const uint RESULT_WORDS = 5;

layout(local_size_x = 64) in;
layout(std430, set = 0, binding = 1) readonly buffer Shapes { ShapeDims shapes[]; };  // at most 8
// Per probe: a ray origin inside the stone, its unit direction, a sample point for the distances.
layout(std430, set = 0, binding = 2) readonly buffer Probes { vec4 probes[]; };
// Per probe: (n, t), (facet, found, first physical step's exit weight, 0), (its exit direction, 0),
// (distance of shapes 0-3 at the sample point), (shapes 4-7).
layout(std430, set = 0, binding = 3) writeonly buffer Results { vec4 results[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (3 * i + 2 >= probes.length()) return;
  vec3 origin = probes[3 * i].xyz, direction = probes[3 * i + 1].xyz, point = probes[3 * i + 2].xyz;

  float t;
  vec3 n;
  int facet;
  bool found = diamondExit(origin, direction, t, n, facet);
  DiamondWalk walk = diamondWalkStart(origin, direction, 1.0, 6);
  vec3 exitDir;
  float exitWeight;
  diamondStep(walk, PROBE_ETA, true, exitDir, exitWeight);
  results[RESULT_WORDS * i] = vec4(n, t);
  results[RESULT_WORDS * i + 1] = vec4(float(facet), found ? 1.0 : 0.0, exitWeight, 0.0);
  results[RESULT_WORDS * i + 2] = vec4(exitDir, 0.0);

  float distances[8];
  for (int k = 0; k < 8; ++k) distances[k] = k < shapes.length() ? shapeSdf(shapes[k], point) : 0.0;
  results[RESULT_WORDS * i + 3] = vec4(distances[0], distances[1], distances[2], distances[3]);
  results[RESULT_WORDS * i + 4] = vec4(distances[4], distances[5], distances[6], distances[7]);
}
