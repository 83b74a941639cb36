// Curl and bitangent noise flows; mirrors src/scenes/noodles/field.h.
#ifndef NOODLES_FIELD_GLSL
#define NOODLES_FIELD_GLSL
#include "noodles/noise.glsl"

const uint FIELD_CURL = 0u;
const uint FIELD_BITANGENT = 1u;

struct FieldSettings {
  uint kind;
  float noiseScale;
  vec3 offsetY;  // second potential, drift included
  vec3 offsetZ;  // third potential, drift included
  float lift;
};

vec3 curlNoise(vec3 q, FieldSettings s) {
  vec3 gx = gradientNoise(q).gradient;
  vec3 gy = gradientNoise(q + s.offsetY).gradient;
  vec3 gz = gradientNoise(q + s.offsetZ).gradient;
  return vec3(gz.y - gy.z, gx.z - gz.x, gy.x - gx.y);
}

vec3 bitangentNoise(vec3 q, FieldSettings s) {
  return cross(gradientNoise(q + s.offsetY).gradient, gradientNoise(q + s.offsetZ).gradient);
}

vec3 flowVelocity(vec3 p, FieldSettings s) {
  vec3 q = p * s.noiseScale;
  vec3 v = s.kind == FIELD_CURL ? curlNoise(q, s) : bitangentNoise(q, s);
  v.z += s.lift;
  return v;
}

#endif
