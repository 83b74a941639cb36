#version 460
// Evaluates the glass optics at given inputs, so a test can hold the GLSL to its C++ mirror.
#extension GL_GOOGLE_include_directive : require
#include "common/hash.glsl"
#include "glass/optics.glsl"

layout(local_size_x = 64) in;
layout(binding = 0, std430) readonly buffer Inputs { vec4 inputs[]; };  // lambda, n_d, V_d, phase in [0, 1)
layout(binding = 1, std430) writeonly buffer Outputs { vec4 outputs[]; };  // four per input, see main
layout(push_constant) uniform Push {
  vec4 sellmeierB;  // xyz: one material's Sellmeier law
  vec4 sellmeierC;
  uint seed;
} pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= inputs.length()) return;
  float lambda = inputs[i].x, nd = inputs[i].y, vd = inputs[i].z, phase = inputs[i].w;
  outputs[4 * i + 0] = vec4(cauchyIor(lambda, nd, vd), sellmeierIor(lambda, pc.sellmeierB.xyz, pc.sellmeierC.xyz),
                            fresnelDielectric(phase, nd), fresnelSchlick(phase, nd));
  outputs[4 * i + 1] = vec4(cieXyz(lambda), stratifiedLambda(int(i % 16u), 16, phase));
  outputs[4 * i + 2] = vec4(spectralWeight(lambda), spectralPhase(uvec2(i, i / 7u), i, pc.seed, true));
  outputs[4 * i + 3] = vec4(filmic(vec3(phase, 4.0 * phase, 16.0 * phase)), heroLambda(i, pc.seed, true));
}
