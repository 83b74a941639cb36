#include "scenes/glass/diamond_walk.h"

#include "scenes/glass/diamond_rays.h"
#include "scenes/glass/optics.h"

#include <glm/geometric.hpp>

#include <optional>

namespace vitrine::glass {

int routeFacet(glm::uvec2 route, int leg) {
  if (leg >= kRouteLegs) return -1;
  const uint32_t facet = (route[leg / 4] >> (8 * (leg % 4))) & 0xffu;
  return facet == 0xffu ? -1 : int(facet);
}

glm::uvec2 withRouteFacet(glm::uvec2 route, int leg, int facet) {
  if (leg >= kRouteLegs) return route;
  const uint32_t shift = 8 * (leg % 4);
  route[leg / 4] = (route[leg / 4] & ~(0xffu << shift)) | (uint32_t(facet) & 0xffu) << shift;
  return route;
}

DiamondWalk diamondWalkStart(glm::vec3 p, glm::vec3 d, float throughput, int maxBounces, glm::uvec2 route) {
  DiamondWalk w;
  w.p = p, w.d = d, w.throughput = throughput, w.maxBounces = maxBounces, w.route = route;
  return w;
}

bool diamondStep(const DiamondGeometry& g, DiamondWalk& w, float eta, bool physical, glm::vec3& exitDir,
                 float& exitWeight) {
  exitDir = w.d, exitWeight = 0.0f;
  if (w.status != kWalking) return false;
  float t;
  glm::vec3 n;
  // The last wavelength's facet for this leg first: tried on its few neighbours, it saves searching all 57.
  int facet = routeFacet(w.route, w.bounces);
  const bool followed = facet >= 0 && facet < kDiamondPlanes && diamondExitThrough(g, w.p, w.d, facet, t, n);
  if (!followed && !diamondExit(g, w.p, w.d, t, n, facet)) {
    w.status = kWalkMissed;
    return false;
  }
  w.p += t * w.d;
  w.facet = facet;
  w.route = withRouteFacet(w.route, w.bounces, facet);
  // From inside to air: the surface normal facing the ray is -n, and the index ratio is 1 / eta.
  const std::optional<glm::vec3> out = refractDir(w.d, -n, 1.0f / eta);
  const glm::vec3 reflected = reflectDir(w.d, n);
  const float r = physical ? fresnelDielectric(glm::dot(w.d, n), 1.0f / eta) : (out ? 0.0f : 1.0f);
  exitDir = out ? *out : reflected;
  exitWeight = w.throughput * (1.0f - r);
  w.throughput *= r;
  // Physical mode stops when what is left could not show (1e-4 of the light that entered); it stays in
  // throughput, so what left plus what is left still adds up to what entered.
  if (w.throughput <= (physical ? 1e-4f : 0.0f)) {
    w.status = kWalkDone;
  } else if (w.bounces >= w.maxBounces) {
    w.status = kWalkExhausted;
  } else {
    w.d = reflected;
    ++w.bounces;
    return true;
  }
  return exitWeight > 0.0f;
}

}  // namespace vitrine::glass
