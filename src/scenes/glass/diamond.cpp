#include "scenes/glass/diamond.h"

#include <glm/gtc/constants.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

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

}  // namespace vitrine::glass
