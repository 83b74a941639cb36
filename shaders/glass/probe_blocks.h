// The glass probes' inputs and results, one declaration for both sides (shaders/common/interop.h says
// how): tests/gpu/glass_optics_probe_test.cpp and glass_diamond_probe_test.cpp fill the inputs and
// hold the results to the C++ reference; optics_probe.comp and diamond_probe.comp evaluate the GLSL.
#ifndef GLASS_PROBE_BLOCKS_H
#define GLASS_PROBE_BLOCKS_H
#include "../common/interop.h"

VITRINE_SHARED_BEGIN
// optics_probe.comp: one input.
struct GlassOpticsProbeInput {
  float lambda;  // nm
  float nd;      // n_d
  float vd;      // V_d
  float phase;   // in [0, 1): the spectral phase, and the cosine for the Fresnel terms
};

// What optics.glsl gives for it.
struct GlassOpticsProbeResult {
  float cauchy;        // cauchyIor(lambda, nd, vd)
  float sellmeier;     // sellmeierIor(lambda) for the push block's law
  float dielectric;    // fresnelDielectric(phase, nd)
  float schlick;       // fresnelSchlick(phase, nd)
  vec3 cie;            // cieXyz(lambda)
  float stratified;    // stratifiedLambda(i % 16, 16, phase)
  vec3 weight;         // spectralWeight(lambda)
  float spectral;      // spectralPhase((i, i / 7), i, seed, true)
  vec3 toneMapped;     // filmic((phase, 4 phase, 16 phase))
  float hero;          // heroLambda(i, seed, true)
};

struct GlassOpticsProbePush {
  vec3 sellmeierB;  // one material's Sellmeier law
  uint seed;
  vec3 sellmeierC;  // µm^2
  uint pad;         // 0
};

// diamond_probe.comp: a ray from inside the stone, and a point where every shape's distance is taken.
struct GlassDiamondProbe {
  vec3 origin;
  float pad0;  // 0: in std430 each vec3 takes 16 bytes
  vec3 direction;  // unit
  float pad1;
  vec3 point;
  float pad2;
};

struct GlassDiamondProbeResult {
  vec3 normal;       // diamondExit's outward normal
  float t;           // and distance along the ray
  int facet;
  uint found;        // 1: diamondExit found an exit
  float exitWeight;  // the first physical walk step's
  uint followed;     // diamondExitThrough's answer: bit 0 for the exit's own facet, bit 1 for the next plane
  vec3 exitDir;      // its exit direction
  float pad1;
  float distances[8];  // shapeSdf of each probe shape at the point (0 past the shapes given)
};
VITRINE_SHARED_END

#endif
