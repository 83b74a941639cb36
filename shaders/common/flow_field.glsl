// Curl and bitangent noise flows; mirrors src/maths/flow_field.h.
#ifndef VITRINE_FLOW_FIELD_GLSL
#define VITRINE_FLOW_FIELD_GLSL
#include "common/noise.glsl"

const uint FIELD_CURL = 0u;
const uint FIELD_BITANGENT = 1u;

struct FieldSettings {
  uint kind;
  float noiseScale;
  vec3 offsetY;  // second potential, drift included
  vec3 offsetZ;  // third potential, drift included
  float lift;
};

// The flows from the gradients of their noise potentials: at q (gx), q + offsetY (gy), q + offsetZ (gz).
vec3 curlOf(vec3 gx, vec3 gy, vec3 gz) {
  NOISE_PRECISE vec3 curl = vec3(gz.y - gy.z, gx.z - gz.x, gy.x - gx.y);
  return curl;
}

vec3 bitangentOf(vec3 gy, vec3 gz) {
  NOISE_PRECISE vec3 t = gy.yzx * gz.zxy - gy.zxy * gz.yzx;  // cross(gy, gz), spelt out to carry `precise`
  return t;
}

vec3 curlNoise(vec3 q, FieldSettings s) {
  NOISE_PRECISE vec3 qy = q + s.offsetY;
  NOISE_PRECISE vec3 qz = q + s.offsetZ;
  return curlOf(gradientNoise(q).gradient, gradientNoise(qy).gradient, gradientNoise(qz).gradient);
}

vec3 bitangentNoise(vec3 q, FieldSettings s) {
  NOISE_PRECISE vec3 qy = q + s.offsetY;
  NOISE_PRECISE vec3 qz = q + s.offsetZ;
  return bitangentOf(gradientNoise(qy).gradient, gradientNoise(qz).gradient);
}

vec3 flowVelocity(vec3 p, FieldSettings s) {
  NOISE_PRECISE vec3 q = p * s.noiseScale;
  NOISE_PRECISE vec3 v = s.kind == FIELD_CURL ? curlNoise(q, s) : bitangentNoise(q, s);
  v.z += s.lift;
  return v;
}

#endif
