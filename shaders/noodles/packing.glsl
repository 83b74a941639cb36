// The 16-byte strand node: position float bits + smallest-three quaternion (10:10:10:2);
// mirrors src/scenes/noodles/packing.h, whose header says why.
#ifndef NOODLES_PACKING_GLSL
#define NOODLES_PACKING_GLSL
#include "noodles/frames.glsl"

const float QUATERNION_RANGE = 0.70710678;
const float QUATERNION_STEPS = 1023.0;
const uint NODE_BLOCK_STRANDS = 32u;  // kNodeBlockStrands

// The same arithmetic as packing.h's loops, written with selects: a dynamically indexed vec4 and a
// loop over it cost the integrate pass a quarter of its time at 10^8 segments on the H200.
uint packQuaternion(vec4 q) {
  vec4 a = abs(q);
  uint largest = 0u;
  float most = a.x;
  if (a.y > most) { largest = 1u; most = a.y; }
  if (a.z > most) { largest = 2u; most = a.z; }
  if (a.w > most) largest = 3u;
  float dropped = largest == 0u ? q.x : largest == 1u ? q.y : largest == 2u ? q.z : q.w;
  if (dropped < 0.0) q = -q;
  vec3 kept = largest == 0u ? q.yzw : largest == 1u ? q.xzw : largest == 2u ? q.xyw : q.xyz;
  vec3 unit = clamp(kept / QUATERNION_RANGE * 0.5 + 0.5, 0.0, 1.0);
  uvec3 steps = uvec3(floor(unit * QUATERNION_STEPS + 0.5));
  return (largest << 30) | steps.x | (steps.y << 10) | (steps.z << 20);
}

vec4 unpackQuaternion(uint bits) {
  int largest = int(bits >> 30);
  vec4 q = vec4(0.0);
  float sumSquares = 0.0;
  int slot = 0;
  for (int i = 0; i < 4; ++i) {
    if (i == largest) continue;
    float unit = float((bits >> (10 * slot++)) & 1023u) / QUATERNION_STEPS;
    q[i] = (unit * 2.0 - 1.0) * QUATERNION_RANGE;
    sumSquares += q[i] * q[i];
  }
  q[largest] = sqrt(max(1.0 - sumSquares, 0.0));
  return q;
}

// src/scenes/noodles/packing.h's nodeSlot says how nodes are laid out and why.
uint nodeSlot(uint chunkStrands, uint nodesPerStrand, uint localStrand, uint node) {
  uint blockStart = localStrand & ~(NODE_BLOCK_STRANDS - 1u);
  uint width = min(NODE_BLOCK_STRANDS, chunkStrands - blockStart);
  return blockStart * nodesPerStrand + node * width + (localStrand - blockStart);
}

uvec4 packNode(vec3 position, Frame frame) {
  return uvec4(floatBitsToUint(position), packQuaternion(frameToQuaternion(frame)));
}

vec3 nodePosition(uvec4 node) { return uintBitsToFloat(node.xyz); }
Frame nodeFrame(uvec4 node) { return quaternionToFrame(unpackQuaternion(node.w)); }

#endif
