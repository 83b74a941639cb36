#include "scenes/glass/diamond_rays.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace vitrine::glass {

float diamondSdf(const DiamondGeometry& g, glm::vec3 p) {
  float d = std::hypot(p.x, p.y) - g.girdleRadius;
  for (const glm::vec4& plane : g.planes) d = std::max(d, glm::dot(glm::vec3(plane), p) - plane.w);
  return d;
}

glm::vec3 diamondNormal(const DiamondGeometry& g, glm::vec3 p, int& facet) {
  float best = std::hypot(p.x, p.y) - g.girdleRadius;
  facet = kGirdleFacet;
  for (int i = 0; i < kDiamondPlanes; ++i) {
    const float d = glm::dot(glm::vec3(g.planes[i]), p) - g.planes[i].w;
    if (d > best) best = d, facet = i;
  }
  if (facet == kGirdleFacet) return glm::normalize(glm::vec3(p.x, p.y, 0.0f));
  return glm::vec3(g.planes[facet]);
}

float diamondEdgeDistance(const DiamondGeometry& g, glm::vec3 p) {
  float first = std::hypot(p.x, p.y) - g.girdleRadius, second = -kInf;
  const float radius = std::max(std::hypot(p.x, p.y), 1e-20f);
  glm::vec3 n1{p.x / radius, p.y / radius, 0.0f}, n2 = n1;
  for (const glm::vec4& plane : g.planes) {
    const float d = glm::dot(glm::vec3(plane), p) - plane.w;
    if (d > first) second = first, n2 = n1, first = d, n1 = glm::vec3(plane);
    else if (d > second) second = d, n2 = glm::vec3(plane);
  }
  return (first - second) / std::max(glm::length(glm::cross(n1, n2)), 1e-3f);
}

bool diamondEnter(const DiamondGeometry& g, glm::vec3 ro, glm::vec3 rd, float& t, glm::vec3& n, int& facet) {
  float tIn = -kInf, tOut = kInf;
  facet = -1;
  for (int i = 0; i < kDiamondPlanes; ++i) {
    const glm::vec3 normal(g.planes[i]);
    const float along = glm::dot(normal, rd), inside = g.planes[i].w - glm::dot(normal, ro);
    if (std::fabs(along) < 1e-8f) {
      if (inside < 0.0f) return false;  // parallel and outside this plane
      continue;
    }
    const float s = inside / along;
    if (along < 0.0f) {
      if (s > tIn) tIn = s, facet = i;
    } else {
      tOut = std::min(tOut, s);
    }
  }
  // The girdle cylinder |xy| = R: enter at the near root, leave at the far one.
  const float a = rd.x * rd.x + rd.y * rd.y, b = ro.x * rd.x + ro.y * rd.y;
  const float c = ro.x * ro.x + ro.y * ro.y - g.girdleRadius * g.girdleRadius;
  if (a < 1e-12f) {
    if (c > 0.0f) return false;
  } else {
    const float disc = b * b - a * c;
    if (disc < 0.0f) return false;
    const float root = std::sqrt(disc);
    const float near = (-b - root) / a, far = (-b + root) / a;
    if (near > tIn) tIn = near, facet = kGirdleFacet;
    tOut = std::min(tOut, far);
  }
  if (facet < 0 || tIn > tOut || tIn < 0.0f) return false;  // missed, or the ray starts inside
  t = tIn;
  const glm::vec3 hit = ro + t * rd;
  n = facet == kGirdleFacet ? glm::normalize(glm::vec3(hit.x, hit.y, 0.0f)) : glm::vec3(g.planes[facet]);
  return true;
}

bool diamondExit(const DiamondGeometry& g, glm::vec3 p, glm::vec3 d, float& t, glm::vec3& n, int& facet) {
  t = kInf;
  facet = -1;
  for (int i = 0; i < kDiamondPlanes; ++i) {
    const glm::vec3 normal(g.planes[i]);
    const float along = glm::dot(normal, d);
    if (along <= 1e-8f) continue;  // the ray does not leave through this plane
    // A point a rounding error outside the plane leaves at once (an edge hit), not behind itself.
    const float s = std::max((g.planes[i].w - glm::dot(normal, p)) / along, 0.0f);
    if (s < t) t = s, facet = i;
  }
  // Leaving the cylinder is always at the far root, also from a point on it after a reflection there.
  const float a = d.x * d.x + d.y * d.y;
  if (a > 1e-12f) {
    const float b = p.x * d.x + p.y * d.y, c = p.x * p.x + p.y * p.y - g.girdleRadius * g.girdleRadius;
    const float s = std::max((-b + std::sqrt(std::max(b * b - a * c, 0.0f))) / a, 0.0f);
    if (s < t) t = s, facet = kGirdleFacet;
  }
  if (facet < 0 || !std::isfinite(t)) return false;
  const glm::vec3 hit = p + t * d;
  n = facet == kGirdleFacet ? glm::normalize(glm::vec3(hit.x, hit.y, 0.0f)) : glm::vec3(g.planes[facet]);
  return true;
}

bool diamondExitThrough(const DiamondGeometry& g, glm::vec3 p, glm::vec3 d, int facet, float& t, glm::vec3& n) {
  const glm::vec3 normal(g.planes[facet]);
  const float along = glm::dot(normal, d);
  if (along <= 1e-8f) return false;
  t = std::max((g.planes[facet].w - glm::dot(normal, p)) / along, 0.0f);
  const glm::vec3 hit = p + t * d;
  const float margin = kEdgeMargin * g.girdleRadius;
  const uint64_t bounds = g.edgeNeighbours[facet];
  if ((bounds >> kGirdleFacet & 1u) != 0u && glm::length(glm::vec2(hit)) > g.girdleRadius - margin) return false;
  for (int j = 0; j < kDiamondPlanes; ++j)
    if ((bounds >> j & 1u) != 0u && glm::dot(glm::vec3(g.planes[j]), hit) - g.planes[j].w > -margin) return false;
  n = normal;
  return true;
}

}  // namespace vitrine::glass
