// The 16-byte strand node: position float bits + smallest-three quaternion (10:10:10:2);
// mirrors src/scenes/noodles/packing.h, whose header says why.
#ifndef NOODLES_PACKING_GLSL
#define NOODLES_PACKING_GLSL
#include "noodles/frames.glsl"

const float QUATERNION_RANGE = 0.70710678;
const float QUATERNION_STEPS = 1023.0;

uint packQuaternion(vec4 q) {
  int largest = 0;
  for (int i = 1; i < 4; ++i)
    if (abs(q[i]) > abs(q[largest])) largest = i;
  if (q[largest] < 0.0) q = -q;
  uint bits = uint(largest) << 30;
  int slot = 0;
  for (int i = 0; i < 4; ++i) {
    if (i == largest) continue;
    float unit = clamp(q[i] / QUATERNION_RANGE * 0.5 + 0.5, 0.0, 1.0);
    bits |= uint(floor(unit * QUATERNION_STEPS + 0.5)) << (10 * slot++);
  }
  return bits;
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

uint nodeSlot(uint chunkStrands, uint localStrand, uint node) { return node * chunkStrands + localStrand; }

uvec4 packNode(vec3 position, Frame frame) {
  return uvec4(floatBitsToUint(position), packQuaternion(frameToQuaternion(frame)));
}

vec3 nodePosition(uvec4 node) { return uintBitsToFloat(node.xyz); }
Frame nodeFrame(uvec4 node) { return quaternionToFrame(unpackQuaternion(node.w)); }

#endif
