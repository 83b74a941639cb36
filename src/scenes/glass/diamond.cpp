#include "scenes/glass/diamond.h"

#include "scenes/glass/optics.h"

#include <glm/gtc/constants.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vitrine::glass {
namespace {

constexpr float kEighth = glm::pi<float>() / 4.0f;  // 45°: the angle between neighbouring mains

glm::vec3 polar(float radius, float azimuth, float z) {
  return {radius * std::cos(azimuth), radius * std::sin(azimuth), z};
}

// A unit outward normal tilted `inclination` degrees from the axis toward `azimuth`; down flips it to the pavilion.
glm::vec3 tilted(float inclination, float azimuth, bool down) {
  const float i = glm::radians(inclination);
  return {std::sin(i) * std::cos(azimuth), std::sin(i) * std::sin(azimuth), down ? -std::cos(i) : std::cos(i)};
}

glm::vec4 planeThrough(glm::vec3 n, glm::vec3 point) { return {n, glm::dot(n, point)}; }

// The point on three planes (Cramer's rule).
glm::vec3 meet(glm::vec4 a, glm::vec4 b, glm::vec4 c) {
  const glm::vec3 na(a), nb(b), nc(c);
  const glm::vec3 bc = glm::cross(nb, nc), ca = glm::cross(nc, na), ab = glm::cross(na, nb);
  return (a.w * bc + b.w * ca + c.w * ab) / glm::dot(na, bc);
}

// The mirror image of a plane in the vertical plane at `azimuth` (the D_8 mirrors).
glm::vec4 mirrored(glm::vec4 plane, float azimuth) {
  const glm::vec2 axis{std::cos(azimuth), std::sin(azimuth)};
  const glm::vec2 xy(plane.x, plane.y);
  const glm::vec2 m = 2.0f * glm::dot(xy, axis) * axis - xy;
  return {m.x, m.y, plane.z, plane.w};
}

int next(int k) { return (k + 1) % 8; }
int previous(int k) { return (k + 7) % 8; }

// The planes (and the girdle) that bound each facet along an edge. Facet i's polygon is found by cutting a
// square on its plane, far wider than the stone, by every other plane in turn, each corner remembering the
// plane its next edge lies on; an edge shorter than a hair is a corner the facet shares, not an edge. Without
// the girdle the crown and pavilion planes still close the stone, so where the polygon reaches past the
// cylinder (or keeps a side of the square) the girdle bounds the facet too. A plane the cylinder makes
// redundant may stay in the set: one plane too many costs a test, one too few would accept a wrong exit.
std::array<uint64_t, kDiamondPlanes> edgeNeighbours(const std::array<glm::vec4, kDiamondPlanes>& planes,
                                                     float girdleRadius) {
  struct Corner {
    glm::vec3 p;
    int edge;  // the plane the edge from here to the next corner lies on; -1 the square's side
  };
  const uint64_t girdle = uint64_t{1} << kGirdleFacet;
  std::array<uint64_t, kDiamondPlanes> bounds{};
  for (int i = 0; i < kDiamondPlanes; ++i) {
    const glm::vec3 n(planes[i]);
    const glm::vec3 u = glm::normalize(glm::cross(n, std::fabs(n.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0)));
    const glm::vec3 v = glm::cross(n, u), centre = n * planes[i].w;
    const float side = 8.0f * girdleRadius;
    std::vector<Corner> polygon = {{centre - side * u - side * v, -1}, {centre + side * u - side * v, -1},
                                   {centre + side * u + side * v, -1}, {centre - side * u + side * v, -1}};
    for (int j = 0; j < kDiamondPlanes; ++j) {
      if (j == i) continue;
      const glm::vec3 m(planes[j]);
      std::vector<Corner> kept;
      for (size_t k = 0; k < polygon.size(); ++k) {
        const Corner& a = polygon[k];
        const Corner& b = polygon[(k + 1) % polygon.size()];
        const float da = glm::dot(m, a.p) - planes[j].w, db = glm::dot(m, b.p) - planes[j].w;
        const auto crossing = [&] { return a.p + (b.p - a.p) * (da / (da - db)); };
        if (da <= 0.0f) kept.push_back(a);
        if (da <= 0.0f && db > 0.0f) kept.push_back({crossing(), j});  // leaves: plane j's edge starts here
        if (da > 0.0f && db <= 0.0f) kept.push_back({crossing(), a.edge});  // comes back along a's edge
      }
      polygon = std::move(kept);
    }
    const float hair = 1e-4f * girdleRadius;
    for (size_t k = 0; k < polygon.size(); ++k) {
      const Corner& a = polygon[k];
      if (glm::length(glm::vec2(a.p)) > girdleRadius * (1.0f - kEdgeMargin)) bounds[i] |= girdle;
      if (glm::distance(a.p, polygon[(k + 1) % polygon.size()].p) < hair) continue;
      bounds[i] |= a.edge < 0 ? girdle : uint64_t{1} << a.edge;
    }
  }
  return bounds;
}

}  // namespace

DiamondGeometry makeDiamond(float diameter) {
  DiamondGeometry g;
  const float r = 0.5f * diameter;
  const float gh = 0.5f * kGirdleRatio * diameter;
  const float tableCorner = kTableRatio * r;
  // Along a main's azimuth the bezel rises from its girdle corner to the table corner, which fixes the crown
  // height: (r - tableCorner)·tan(34.5°) = 16.2 % of the diameter, Tolkowsky's figure.
  const float tableZ = gh + (r - tableCorner) * std::tan(glm::radians(kCrownAngle));
  const float culetZ = -gh - r * std::tan(glm::radians(kPavilionAngle));
  g.diameter = diameter;
  g.girdleRadius = r;
  g.girdleHalfHeight = gh;
  g.tableHeight = tableZ;
  g.culetDepth = -culetZ;
  auto& v = g.vertices;
  v.culet = {0.0f, 0.0f, culetZ};

  auto set = [&](int i, FacetKind kind, std::string name, glm::vec4 plane) {
    g.planes[i] = plane, g.kinds[i] = kind, g.names[i] = std::move(name);
  };
  set(0, FacetKind::Table, "table", {0.0f, 0.0f, 1.0f, tableZ});

  for (int k = 0; k < 8; ++k) {
    const float main = k * kEighth, star = main + 0.5f * kEighth;
    v.table[k] = polar(tableCorner, main, tableZ);
    v.girdleTopMain[k] = polar(r, main, gh);
    v.girdleBottomMain[k] = polar(r, main, -gh);
    v.girdleBottomStar[k] = polar(r, star, -gh);
    const std::string index = std::to_string(k);
    // Bezels and mains touch the girdle circle with their lowest (highest) corner.
    set(1 + k, FacetKind::Bezel, "bezel " + index, planeThrough(tilted(kCrownAngle, main, false), v.girdleTopMain[k]));
    set(33 + k, FacetKind::PavilionMain, "pavilion main " + index,
        planeThrough(tilted(kPavilionAngle, main, true), v.girdleBottomMain[k]));
    // A star leans on its table edge.
    const glm::vec3 edgeMiddle = polar(tableCorner * std::cos(0.5f * kEighth), star, tableZ);
    set(9 + k, FacetKind::Star, "star " + index, planeThrough(tilted(kStarAngle, star, false), edgeMiddle));
    // A lower-half pair spans the girdle from main k to main k+1, meeting at the star azimuth: each half holds
    // a horizontal chord of the girdle's bottom circle, so its normal points at the chord's middle.
    const glm::vec4 lower = planeThrough(tilted(kLowerHalfAngle, main + 0.25f * kEighth, true), v.girdleBottomMain[k]);
    set(41 + 2 * k, FacetKind::LowerHalf, "lower half " + index + "a", lower);
    set(42 + 2 * k, FacetKind::LowerHalf, "lower half " + index + "b", mirrored(lower, star));
  }

  for (int k = 0; k < 8; ++k) {
    const float main = k * kEighth, star = main + 0.5f * kEighth;
    const std::string index = std::to_string(k);
    v.star[k] = meet(g.planes[1 + k], g.planes[1 + next(k)], g.planes[9 + k]);
    v.lowerTip[k] = meet(g.planes[33 + k], g.planes[33 + next(k)], g.planes[41 + 2 * k]);
    // An upper half runs from the star point S to bezel k's girdle corner G. A normal tilted u toward azimuth a
    // is square to S - G when rho·cos(a - alpha)·sin(u) = -span.z·cos(u) (rho, alpha: the span's polar xy):
    // two azimuths; take the one between the main's and the star's.
    const glm::vec3 span = v.star[k] - v.girdleTopMain[k];
    const float u = glm::radians(kUpperHalfAngle);
    const float rho = std::hypot(span.x, span.y), alpha = std::atan2(span.y, span.x);
    const float spread = std::acos(glm::clamp(-span.z / (std::tan(u) * rho), -1.0f, 1.0f));
    const float a = alpha + spread, b = alpha - spread;
    auto offMiddle = [&](float x) {
      return std::fabs(std::remainder(x - (main + 0.25f * kEighth), glm::two_pi<float>()));
    };
    const glm::vec4 upper = planeThrough(tilted(kUpperHalfAngle, offMiddle(a) < offMiddle(b) ? a : b, false),
                                         v.girdleTopMain[k]);
    set(17 + 2 * k, FacetKind::UpperHalf, "upper half " + index + "a", upper);
    set(18 + 2 * k, FacetKind::UpperHalf, "upper half " + index + "b", mirrored(upper, star));
    // The pair meets the girdle cylinder at the star azimuth, at whatever height the 39.9° plane reaches there.
    const glm::vec3 onAxis = polar(r, star, 0.0f);
    v.girdleTopStar[k] = {onAxis.x, onAxis.y, (upper.w - upper.x * onAxis.x - upper.y * onAxis.y) / upper.z};
  }
  g.edgeNeighbours = edgeNeighbours(g.planes, r);
  return g;
}

const DiamondGeometry& cachedDiamond(float diameter) {
  thread_local DiamondGeometry g;
  if (g.diameter != diameter) g = makeDiamond(diameter);
  return g;
}

std::vector<glm::vec3> diamondFacetCorners(const DiamondGeometry& g, int facet) {
  const auto& v = g.vertices;
  if (facet == 0) return {v.table.begin(), v.table.end()};
  if (facet <= 8) {
    const int k = facet - 1;
    return {v.table[k], v.star[previous(k)], v.girdleTopMain[k], v.star[k]};
  }
  if (facet <= 16) {
    const int k = facet - 9;
    return {v.table[k], v.star[k], v.table[next(k)]};
  }
  if (facet <= 32) {
    const int k = (facet - 17) / 2;
    if ((facet - 17) % 2 == 0) return {v.star[k], v.girdleTopMain[k], v.girdleTopStar[k]};
    return {v.star[k], v.girdleTopStar[k], v.girdleTopMain[next(k)]};
  }
  if (facet <= 40) {
    const int k = facet - 33;
    return {v.girdleBottomMain[k], v.lowerTip[previous(k)], v.culet, v.lowerTip[k]};
  }
  if (facet <= 56) {
    const int k = (facet - 41) / 2;
    if ((facet - 41) % 2 == 0) return {v.girdleBottomMain[k], v.lowerTip[k], v.girdleBottomStar[k]};
    return {v.girdleBottomStar[k], v.lowerTip[k], v.girdleBottomMain[next(k)]};
  }
  return {};
}

shader::GlassDiamond diamondBlock(const DiamondGeometry& g) {
  shader::GlassDiamond block{.girdleRadius = g.girdleRadius,
                             .girdleHalfHeight = g.girdleHalfHeight,
                             .tableHeight = g.tableHeight,
                             .culetDepth = g.culetDepth};
  std::copy(g.planes.begin(), g.planes.end(), block.planes);
  for (int i = 0; i < kDiamondPlanes; ++i)
    block.edgeNeighbours[i] = {uint32_t(g.edgeNeighbours[i]), uint32_t(g.edgeNeighbours[i] >> 32)};
  return block;
}

std::vector<glm::vec3> diamondHullTriangles(const DiamondGeometry& g) {
  const auto& v = g.vertices;
  // The girdle band lies in the convex hull of two circles: z = -gh and z = top, the highest the girdle's top
  // edge reaches (the upper halves meet the cylinder a hair above +gh at the star azimuths).
  float top = g.girdleHalfHeight;
  for (const glm::vec3& p : v.girdleTopStar) top = std::max(top, p.z);
  const float middle = 0.5f * (top - g.girdleHalfHeight);

  // One 16-gon at the band's middle (corners at the mains' and stars' azimuths) joins the crown's table and star
  // points to the pavilion's lower-half tips and culet; `reach` past the girdle radius is what lets the faces
  // either side of it clear the band's circles.
  auto build = [&](float reach) {
    const float corner = (g.girdleRadius + reach) / std::cos(0.25f * kEighth);
    auto ring = [&](int j) { return polar(corner, (j % 16) * 0.5f * kEighth, middle); };
    std::vector<glm::vec3> out;
    // A triangle facing away from the stone's centre (the hull is convex and holds the origin).
    auto triangle = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c) {
      if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0.0f) std::swap(b, c);
      out.insert(out.end(), {a, b, c});
    };
    for (int k = 1; k < 7; ++k) triangle(v.table[0], v.table[k], v.table[k + 1]);
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 atMain = ring(2 * k), atStar = ring(2 * k + 1), atNext = ring(2 * k + 2);
      // Crown: the star, the bezel split along its axis (its girdle corner moved out to the ring), two halves.
      triangle(v.table[k], v.table[next(k)], v.star[k]);
      triangle(v.table[k], atMain, v.star[k]);
      triangle(v.table[next(k)], v.star[k], atNext);
      triangle(v.star[k], atMain, atStar);
      triangle(v.star[k], atStar, atNext);
      // Pavilion: two lower halves, the main split along its axis.
      triangle(atMain, v.lowerTip[k], atStar);
      triangle(atStar, v.lowerTip[k], atNext);
      triangle(atMain, v.culet, v.lowerTip[k]);
      triangle(atNext, v.lowerTip[k], v.culet);
    }
    return out;
  };
  // A circle's farthest point along a face normal n is at R·|n.xy| + n.z·z: an exact test, no sampling.
  auto holdsBand = [&](const std::vector<glm::vec3>& tris) {
    for (size_t i = 0; i < tris.size(); i += 3) {
      const glm::vec3 n = glm::normalize(glm::cross(tris[i + 1] - tris[i], tris[i + 2] - tris[i]));
      const float d = glm::dot(n, tris[i]), radial = g.girdleRadius * std::hypot(n.x, n.y);
      if (radial + n.z * top > d || radial - n.z * g.girdleHalfHeight > d) return false;
    }
    return true;
  };
  // The least reach that holds the band, by bisection (about 1.5 % of the radius for the ideal cut).
  float lo = 0.0f, hi = 0.25f * g.girdleRadius;
  for (int i = 0; i < 24; ++i) {
    const float mid = 0.5f * (lo + hi);
    (holdsBand(build(mid)) ? hi : lo) = mid;
  }
  return build(hi);
}

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
