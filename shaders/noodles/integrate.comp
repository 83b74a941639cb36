#version 460
// The strands in the exact flow: every step evaluates the noise (integrate_strands.glsl does the rest).
#extension GL_GOOGLE_include_directive : require
#include "noodles/integrate_strands.glsl"

vec3 strandVelocity(vec3 p, FieldSettings field) { return flowVelocity(p, field); }
