#pragma once
// The interior walk (diamond.h's stone): light that entered, bouncing off facets until it leaves or the
// budget ends, each leg split by Fresnel (or the seed's all-or-nothing). Mirrored by shaders/glass/diamond.glsl.
#include "scenes/glass/diamond.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace vitrine::glass {

enum DiamondWalkStatus : int { kWalking = 0, kWalkDone = 1, kWalkExhausted = 2, kWalkMissed = 3 };

// The facets a walk left through, leg by leg, a byte each for its first kRouteLegs legs (0xff: none). The
// wavelengths of one pixel mostly take the same route through the stone, so each walk first tries the
// previous wavelength's facet for a leg (diamondExitThrough) and searches all 57 only where that fails.
inline constexpr int kRouteLegs = shader::kGlassRouteLegs;
inline constexpr glm::uvec2 kNoRoute{0xffffffffu, 0xffffffffu};
int routeFacet(glm::uvec2 route, int leg);  // -1: no facet known for this leg
glm::uvec2 withRouteFacet(glm::uvec2 route, int leg, int facet);

struct DiamondWalk {
  glm::vec3 p{};            // where the ray is (on a facet after the first step)
  glm::vec3 d{};            // its unit direction, inside the stone
  float throughput = 1.0f;  // the share of the entering light still inside
  int facet = -1;           // the facet the ray last met (-1 at the start)
  int bounces = 0;          // internal reflections so far
  int status = kWalking;
  int maxBounces = 6;       // internal reflections allowed (the UI's 1-32)
  glm::uvec2 route = kNoRoute;  // in: the facets to try first; out: the facets this walk left through
};

DiamondWalk diamondWalkStart(glm::vec3 p, glm::vec3 d, float throughput, int maxBounces, glm::uvec2 route = kNoRoute);

// One leg of the walk: finds the next exit and splits the light there. eta = n_diamond / n_air at this
// wavelength. Seed mode (physical = false): leaves whole if it can refract out, else reflects whole (TIR).
// Physical mode: the exact Fresnel share R reflects on, 1 - R leaves. exitWeight is the light leaving now,
// along exitDir (a valid unit vector even when exitWeight is 0, so env(exitDir) never sees a NaN).
// Returns false once nothing more will leave: then status says why and throughput holds what is left inside.
bool diamondStep(const DiamondGeometry& g, DiamondWalk& w, float eta, bool physical, glm::vec3& exitDir,
                 float& exitWeight);

}  // namespace vitrine::glass
