#version 460
// Evaluates the glass optics at given inputs, so a test can hold the GLSL to its C++ mirror.
#extension GL_GOOGLE_include_directive : require
#include "common/hash.glsl"
#include "glass/optics.glsl"
#include "glass/probe_blocks.h"

layout(local_size_x = 64) in;
layout(binding = 0, std430) readonly buffer Inputs { GlassOpticsProbeInput inputs[]; };
layout(binding = 1, std430) writeonly buffer Results { GlassOpticsProbeResult results[]; };  // one per input
layout(push_constant) uniform Push { GlassOpticsProbePush pc; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= inputs.length()) return;
  const GlassOpticsProbeInput at = inputs[i];
  GlassOpticsProbeResult r;
  r.cauchy = cauchyIor(at.lambda, at.nd, at.vd);
  r.sellmeier = sellmeierIor(at.lambda, pc.sellmeierB, pc.sellmeierC);
  r.dielectric = fresnelDielectric(at.phase, at.nd);
  r.schlick = fresnelSchlick(at.phase, at.nd);
  r.cie = cieXyz(at.lambda);
  r.stratified = stratifiedLambda(int(i % 16u), 16, at.phase);
  r.weight = spectralWeight(at.lambda);
  r.spectral = spectralPhase(uvec2(i, i / 7u), i, pc.seed, true);
  r.toneMapped = filmic(vec3(at.phase, 4.0 * at.phase, 16.0 * at.phase));
  r.hero = heroLambda(i, pc.seed, true);
  results[i] = r;
}
