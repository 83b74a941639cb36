// The round brilliant (src/scenes/glass/diamond.h, diamond_rays.h, diamond_walk.h): facet planes against
// the proportions, the polytope's vertices and symmetry, the proxy hull, ray-polytope hits against
// marching, and the interior walk.
#include "maths/hash.h"
#include "scenes/glass/diamond.h"
#include "scenes/glass/diamond_rays.h"
#include "scenes/glass/diamond_walk.h"
#include "scenes/glass/optics.h"
#include "scenes/glass/shapes.h"
#include "support/random_vectors.h"
#include "support/trials.h"

#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace vitrine::glass {
namespace {

constexpr float kDiameter = 400.0f;
constexpr float kLength = 1e-4f * kDiameter;  // positions agree to this
constexpr float kEta = 2.4175f;              // diamond at the brief's wavelength

const DiamondGeometry& stone() {
  static const DiamondGeometry g = makeDiamond(kDiameter);
  return g;
}

using test::randomDirection;
using test::randomSigned;
glm::vec3 randomInside(uint32_t& i) {
  const glm::vec3 half{0.5f * kDiameter, 0.5f * kDiameter, stone().culetDepth};
  for (;; ++i) {
    const glm::vec3 p = randomSigned(i, 11u) * half;
    if (diamondSdf(stone(), p) < -1e-3f * kDiameter) return p;
  }
}

float planeTerm(const glm::vec4& plane, glm::vec3 p) { return glm::dot(glm::vec3(plane), p) - plane.w; }

glm::vec4 turned(glm::vec4 plane, float angle) {
  const glm::vec3 n = rotationZ(angle) * glm::vec3(plane);
  return {n, plane.w};
}
glm::vec4 mirroredInY(glm::vec4 plane) { return {plane.x, -plane.y, plane.z, plane.w}; }

// The facet (or -1) whose plane equals `plane`.
int facetOfPlane(const glm::vec4& plane) {
  for (int i = 0; i < kDiamondPlanes; ++i)
    if (glm::distance(glm::vec3(stone().planes[i]), glm::vec3(plane)) < 1e-5f &&
        std::fabs(stone().planes[i].w - plane.w) < kLength)
      return i;
  return -1;
}

glm::vec3 centreOf(const std::vector<glm::vec3>& points) {
  glm::vec3 sum(0.0f);
  for (const glm::vec3& p : points) sum += p;
  return sum / float(points.size());
}

// --- The planes, facet by facet.

class Facet : public ::testing::TestWithParam<int> {
 protected:
  int index() const { return GetParam(); }
  const glm::vec4& plane() const { return stone().planes[index()]; }
  FacetKind kind() const { return stone().kinds[index()]; }
};

TEST_P(Facet, UnitOutwardNormalThroughItsCorners) {
  EXPECT_NEAR(glm::length(glm::vec3(plane())), 1.0f, 1e-6f);
  EXPECT_GT(plane().w, 0.0f);  // the centre is inside
  const std::vector<glm::vec3> corners = diamondFacetCorners(stone(), index());
  ASSERT_GE(corners.size(), 3u);
  for (const glm::vec3& c : corners) EXPECT_NEAR(planeTerm(plane(), c), 0.0f, kLength) << stone().names[index()];
}

TEST_P(Facet, CornersLieInsideEveryOtherPlaneAndTheGirdle) {
  for (const glm::vec3& c : diamondFacetCorners(stone(), index())) {
    EXPECT_LE(std::hypot(c.x, c.y), stone().girdleRadius + kLength);
    for (int j = 0; j < kDiamondPlanes; ++j)
      ASSERT_LE(planeTerm(stone().planes[j], c), kLength) << stone().names[index()] << " vs " << stone().names[j];
  }
}

TEST_P(Facet, InclinationMatchesTheProportions) {
  static const std::map<FacetKind, float> expected = {{FacetKind::Table, 0.0f},
                                                      {FacetKind::Bezel, kCrownAngle},
                                                      {FacetKind::Star, kStarAngle},
                                                      {FacetKind::UpperHalf, kUpperHalfAngle},
                                                      {FacetKind::PavilionMain, kPavilionAngle},
                                                      {FacetKind::LowerHalf, kLowerHalfAngle}};
  const bool crown = index() <= 32;
  EXPECT_EQ(plane().z > 0.0f, crown);
  const float inclination = glm::degrees(std::acos(glm::clamp(std::fabs(plane().z), 0.0f, 1.0f)));
  EXPECT_NEAR(inclination, expected.at(kind()), 1e-3f) << stone().names[index()];
}

TEST_P(Facet, AzimuthFollowsTheEightfoldLayout) {
  if (kind() == FacetKind::Table) {
    EXPECT_EQ(glm::vec3(plane()), glm::vec3(0.0f, 0.0f, 1.0f));  // no azimuth: level
    return;
  }
  const float azimuth = std::atan2(plane().y, plane().x);
  const float step = glm::quarter_pi<float>();
  auto near = [&](float target) { return std::fabs(std::remainder(azimuth - target, glm::two_pi<float>())) < 1e-4f; };
  switch (kind()) {
    case FacetKind::Bezel: EXPECT_TRUE(near((index() - 1) * step)); break;
    case FacetKind::PavilionMain: EXPECT_TRUE(near((index() - 33) * step)); break;
    case FacetKind::Star: EXPECT_TRUE(near((index() - 9 + 0.5f) * step)); break;
    case FacetKind::LowerHalf: {
      // Each half of pair k holds a horizontal girdle chord: its normal points at the chord's middle.
      const int k = (index() - 41) / 2, b = (index() - 41) % 2;
      EXPECT_TRUE(near((k + 0.25f + 0.5f * b) * step));
      break;
    }
    case FacetKind::UpperHalf: {
      // Between the main and the star azimuths (a), or its mirror (b); the two mirror about the star azimuth.
      const int k = (index() - 17) / 2, b = (index() - 17) % 2;
      const float offset = std::remainder(azimuth - (k + 0.5f) * step, glm::two_pi<float>());
      EXPECT_GT(b ? offset : -offset, 0.0f);
      EXPECT_LT(std::fabs(offset), 0.5f * step);
      EXPECT_EQ(facetOfPlane(turned(mirroredInY(turned(plane(), -(k + 0.5f) * step)), (k + 0.5f) * step)),
                b ? index() - 1 : index() + 1);
      break;
    }
    default: break;
  }
}

TEST_P(Facet, EightfoldImagesAreFacetsOfTheSameKind) {
  for (int k = 1; k < 8; ++k) {
    const int image = facetOfPlane(turned(plane(), k * glm::quarter_pi<float>()));
    ASSERT_GE(image, 0) << "turned by " << k * 45 << " degrees";
    EXPECT_EQ(stone().kinds[image], kind());
    if (kind() != FacetKind::Table) {
      EXPECT_NE(image, index());
    }
  }
  const int mirrored = facetOfPlane(mirroredInY(plane()));
  ASSERT_GE(mirrored, 0);
  EXPECT_EQ(stone().kinds[mirrored], kind());
}

TEST_P(Facet, CornersWindCounterClockwiseSeenFromOutside) {
  const std::vector<glm::vec3> c = diamondFacetCorners(stone(), index());
  for (size_t i = 0; i < c.size(); ++i) {
    const glm::vec3 a = c[i], b = c[(i + 1) % c.size()], d = c[(i + 2) % c.size()];
    EXPECT_GT(glm::dot(glm::cross(b - a, d - b), glm::vec3(plane())), 0.0f)
        << stone().names[index()] << " corner " << i;
  }
}

TEST_P(Facet, IsOnTheSurfaceAtTheCentreOfItsCorners) {
  const glm::vec3 centre = centreOf(diamondFacetCorners(stone(), index()));
  EXPECT_NEAR(diamondSdf(stone(), centre), 0.0f, kLength);
  int facet;
  EXPECT_EQ(diamondNormal(stone(), centre, facet), glm::vec3(plane()));
  EXPECT_EQ(facet, index());
  EXPECT_GT(diamondEdgeDistance(stone(), centre), 0.5f);  // well away from any edge
}

INSTANTIATE_TEST_SUITE_P(AllPlanes, Facet, ::testing::Range(0, kDiamondPlanes),
                         [](const ::testing::TestParamInfo<int>& test) {
                           std::string name = stone().names[test.param];
                           for (char& c : name)
                             if (c == ' ') c = '_';
                           return name;
                         });

// --- The stone as a whole.

TEST(Diamond, FiftySevenPlanesOfSixKinds) {
  std::map<FacetKind, int> count;
  for (FacetKind k : stone().kinds) ++count[k];
  EXPECT_EQ(count[FacetKind::Table], 1);
  EXPECT_EQ(count[FacetKind::Bezel], 8);
  EXPECT_EQ(count[FacetKind::Star], 8);
  EXPECT_EQ(count[FacetKind::UpperHalf], 16);
  EXPECT_EQ(count[FacetKind::PavilionMain], 8);
  EXPECT_EQ(count[FacetKind::LowerHalf], 16);
  EXPECT_EQ(std::set<std::string>(stone().names.begin(), stone().names.end()).size(), 57u);
  EXPECT_EQ(kGirdleFacet, 57);
}

TEST(Diamond, ProportionsOfTheIdealCut) {
  const DiamondGeometry& g = stone();
  EXPECT_FLOAT_EQ(g.girdleRadius, 200.0f);
  EXPECT_NEAR(2.0f * g.girdleHalfHeight / kDiameter, 0.02f, 1e-6f);
  for (const glm::vec3& c : g.vertices.table) {
    EXPECT_NEAR(2.0f * std::hypot(c.x, c.y) / kDiameter, 0.53f, 1e-5f);  // table 53 %, corner to corner
    EXPECT_FLOAT_EQ(c.z, g.tableHeight);
  }
  EXPECT_NEAR((g.tableHeight - g.girdleHalfHeight) / kDiameter, 0.162f, 1e-3f);  // Tolkowsky's crown height
  EXPECT_NEAR((g.culetDepth - g.girdleHalfHeight) / kDiameter, 0.431f, 1e-3f);   // and pavilion depth
  EXPECT_EQ(g.vertices.culet, glm::vec3(0.0f, 0.0f, -g.culetDepth));
  for (int k = 0; k < 8; ++k) {  // the mains' girdle corners sit on the band's edges
    EXPECT_NEAR(g.vertices.girdleTopMain[k].z, g.girdleHalfHeight, 1e-6f);
    EXPECT_NEAR(g.vertices.girdleBottomMain[k].z, -g.girdleHalfHeight, 1e-6f);
    EXPECT_NEAR(g.vertices.girdleBottomStar[k].z, -g.girdleHalfHeight, 1e-6f);
    EXPECT_NEAR(g.vertices.girdleTopStar[k].z, g.girdleHalfHeight, 0.1f * g.girdleHalfHeight);  // 39.9° lands near
  }
  // The star and lower-half lengths that follow: about half-way down the crown, three quarters of the pavilion.
  const float starReach = std::hypot(g.vertices.star[0].x, g.vertices.star[0].y) / g.girdleRadius;
  const float tableEdge = 0.53f * std::cos(glm::pi<float>() / 8.0f);
  EXPECT_NEAR((starReach - tableEdge) / (1.0f - tableEdge), 0.45f, 0.05f);
  EXPECT_NEAR(1.0f - std::hypot(g.vertices.lowerTip[0].x, g.vertices.lowerTip[0].y) / g.girdleRadius, 0.75f, 0.03f);
}

TEST(Diamond, ScalesWithItsDiameter) {
  const DiamondGeometry small = makeDiamond(1.0f);
  for (int i = 0; i < kDiamondPlanes; ++i) {
    EXPECT_NEAR(glm::distance(glm::vec3(small.planes[i]), glm::vec3(stone().planes[i])), 0.0f, 1e-5f);
    EXPECT_NEAR(small.planes[i].w * kDiameter, stone().planes[i].w, kLength);
  }
  const DiamondGeometry& cached = cachedDiamond(kDiameter);
  EXPECT_EQ(cached.planes, stone().planes);
  EXPECT_EQ(cachedDiamond(1.0f).planes, small.planes);
}

// Every point where three planes meet inside all planes and the girdle is one of the named vertices, and each
// named one is found: the corner lists describe the real polytope, with no facet clipped to another shape.
TEST(Diamond, PolytopeVerticesAreTheNamedOnes) {
  const DiamondGeometry& g = stone();
  const auto& v = g.vertices;
  std::vector<glm::vec3> named(v.table.begin(), v.table.end());
  for (const auto* group : {&v.star, &v.lowerTip, &v.girdleTopMain, &v.girdleBottomMain})
    named.insert(named.end(), group->begin(), group->end());
  named.push_back(v.culet);
  std::vector<int> found(named.size(), 0);
  for (int a = 0; a < kDiamondPlanes; ++a)
    for (int b = a + 1; b < kDiamondPlanes; ++b)
      for (int c = b + 1; c < kDiamondPlanes; ++c) {
        const glm::vec3 na(g.planes[a]), nb(g.planes[b]), nc(g.planes[c]);
        const float det = glm::dot(na, glm::cross(nb, nc));
        if (std::fabs(det) < 1e-4f) continue;
        const glm::vec3 p = (g.planes[a].w * glm::cross(nb, nc) + g.planes[b].w * glm::cross(nc, na) +
                             g.planes[c].w * glm::cross(na, nb)) /
                            det;
        if (diamondSdf(g, p) > 1e-3f) continue;  // outside the stone
        size_t match = 0;
        while (match < named.size() && glm::distance(named[match], p) > 1e-2f) ++match;
        ASSERT_LT(match, named.size()) << g.names[a] << ", " << g.names[b] << ", " << g.names[c] << " meet at " << p.x
                                       << " " << p.y << " " << p.z;
        ++found[match];
      }
  for (size_t i = 0; i < named.size(); ++i) EXPECT_GT(found[i], 0) << "named vertex " << i;
}

TEST(Diamond, GirdleBandIsWholeAllTheWayRound) {
  const DiamondGeometry& g = stone();
  float thinnest = 1e9f;
  for (int j = 0; j < 3600; ++j) {
    const float a = j * glm::two_pi<float>() / 3600.0f;
    const glm::vec2 xy = g.girdleRadius * glm::vec2(std::cos(a), std::sin(a));
    float top = 1e9f, bottom = -1e9f;  // the crown's lowest and the pavilion's highest plane over this point
    for (const glm::vec4& p : g.planes) {
      const float z = (p.w - p.x * xy.x - p.y * xy.y) / p.z;
      if (p.z > 0.0f) top = glm::min(top, z);
      else bottom = glm::max(bottom, z);
    }
    thinnest = glm::min(thinnest, top - bottom);
    ASSERT_LE(top, g.girdleHalfHeight * 1.05f);
    ASSERT_GE(bottom, -g.girdleHalfHeight - 1e-4f);
  }
  // Scalloped by the halves (as in real stones), but never pinched through.
  EXPECT_GT(thinnest, 0.1f * g.girdleHalfHeight);
}

TEST(Diamond, DistanceOnKnownPoints) {
  const DiamondGeometry& g = stone();
  EXPECT_NEAR(diamondSdf(g, {0.0f, 0.0f, g.tableHeight + 5.0f}), 5.0f, 1e-4f);
  EXPECT_NEAR(diamondSdf(g, {0.0f, 0.0f, g.tableHeight - 5.0f}), -5.0f, 1e-4f);
  EXPECT_NEAR(diamondSdf(g, {g.girdleRadius + 3.0f, 0.0f, 0.0f}), 3.0f, 1e-4f);
  EXPECT_NEAR(diamondSdf(g, {0.0f, -g.girdleRadius - 3.0f, 0.0f}), 3.0f, 1e-4f);
  EXPECT_NEAR(diamondSdf(g, g.vertices.culet), 0.0f, 1e-3f);
  EXPECT_GT(diamondSdf(g, g.vertices.culet - glm::vec3(0.0f, 0.0f, 5.0f)), 3.0f);  // a bound below the point
  // Straight out from a facet's middle the distance is exact.
  const glm::vec3 bezel = centreOf(diamondFacetCorners(g, 3));
  EXPECT_NEAR(diamondSdf(g, bezel + 4.0f * glm::vec3(g.planes[3])), 4.0f, 1e-3f);
  EXPECT_NEAR(diamondSdf(g, bezel - 4.0f * glm::vec3(g.planes[3])), -4.0f, 1e-3f);
}

TEST(Diamond, EdgeDistanceVanishesOnEdges) {
  const DiamondGeometry& g = stone();
  const auto& v = g.vertices;
  for (int k = 0; k < 8; ++k) {
    EXPECT_NEAR(diamondEdgeDistance(g, 0.5f * (v.table[k] + v.star[k])), 0.0f, 1e-3f);        // bezel | star
    EXPECT_NEAR(diamondEdgeDistance(g, 0.5f * (v.lowerTip[k] + v.culet)), 0.0f, 1e-3f);       // main | main
    EXPECT_NEAR(diamondEdgeDistance(g, 0.5f * (v.table[k] + v.table[(k + 1) % 8])), 0.0f, 1e-3f);  // table | star
  }
  EXPECT_GT(diamondEdgeDistance(g, {0.0f, 0.0f, g.tableHeight}), 10.0f);  // the table's middle
  // A true distance along the facet: from the table's centre to its edges is the octagon's apothem.
  const float apothem = glm::length(glm::vec2(v.table[0])) * std::cos(glm::pi<float>() / 8.0f);
  EXPECT_NEAR(diamondEdgeDistance(g, {0.0f, 0.0f, g.tableHeight}), apothem, 1e-3f * g.diameter);
}

// The block's layout is the build's to check (shaders/glass/diamond_blocks.h); its values are these.
TEST(Diamond, TheShaderBlockHoldsThePlanesAndTheGirdle) {
  const shader::GlassDiamond block = diamondBlock(stone());
  for (int i = 0; i < kDiamondPlanes; ++i) EXPECT_EQ(block.planes[i], stone().planes[i]);
  EXPECT_EQ(block.girdleRadius, stone().girdleRadius);
  EXPECT_EQ(block.girdleHalfHeight, stone().girdleHalfHeight);
  EXPECT_EQ(block.tableHeight, stone().tableHeight);
  EXPECT_EQ(block.culetDepth, stone().culetDepth);
}

// A facet's edge neighbours hold the facets its corners say it shares an edge with (two corners in common),
// and the girdle where a corner lies on the cylinder: the clipped polygons and the constructed corners agree.
TEST(Diamond, EdgeNeighboursAreTheFacetsSharingTwoCorners) {
  const DiamondGeometry& g = stone();
  auto shared = [&](int a, int b) {
    int common = 0;
    for (const glm::vec3& p : diamondFacetCorners(g, a))
      for (const glm::vec3& q : diamondFacetCorners(g, b)) common += glm::distance(p, q) < kLength ? 1 : 0;
    return common;
  };
  auto onGirdle = [&](int facet) {
    bool touches = false;
    for (const glm::vec3& p : diamondFacetCorners(g, facet))
      touches = touches || std::fabs(glm::length(glm::vec2(p)) - g.girdleRadius) < kLength;
    return touches;
  };
  const uint64_t girdle = uint64_t{1} << kGirdleFacet;
  for (int i = 0; i < kDiamondPlanes; ++i) {
    uint64_t expected = 0;
    for (int j = 0; j < kDiamondPlanes; ++j)
      if (j != i && shared(i, j) >= 2) expected |= uint64_t{1} << j;
    // Clipped without the cylinder, two facets that reach the girdle may also meet beyond it, outside the
    // stone: one test too many, never one too few.
    const uint64_t found = g.edgeNeighbours[i] & ~girdle;
    EXPECT_EQ(found & expected, expected) << g.names[i];
    for (int j = 0; j < kDiamondPlanes; ++j)
      if ((found & ~expected) >> j & 1u) {
        EXPECT_TRUE(onGirdle(i) && onGirdle(j)) << g.names[i] << ", " << g.names[j];
      }
    // Bezels and pavilion mains meet the girdle at one corner only: for them the bit is allowed, not asked.
    if (onGirdle(i) && g.kinds[i] != FacetKind::Bezel && g.kinds[i] != FacetKind::PavilionMain) {
      EXPECT_NE(g.edgeNeighbours[i] & girdle, 0u) << g.names[i];
    }
    if (!onGirdle(i)) {
      EXPECT_EQ(g.edgeNeighbours[i] & girdle, 0u) << g.names[i];
    }
  }
  EXPECT_EQ(std::popcount(g.edgeNeighbours[0]), 8);  // the table: the eight stars
  const shader::GlassDiamond block = diamondBlock(g);
  for (int i = 0; i < kDiamondPlanes; ++i)
    EXPECT_EQ(block.edgeNeighbours[i], glm::uvec2(uint32_t(g.edgeNeighbours[i]), uint32_t(g.edgeNeighbours[i] >> 32)));
}

// Tried on one facet, the exit is accepted on the facet diamondExit finds, at its distance, and on no other.
TEST(DiamondRays, AnExitTriedOnOneFacetIsAcceptedOnlyWhereItIs) {
  uint32_t seed = 0;
  int accepted = 0, tried = 0;
  for (uint32_t i = 0; i < 4000; ++i, ++seed) {
    const glm::vec3 p = randomInside(seed), d = randomDirection(i, 67u);
    float t, tried_t;
    glm::vec3 n, triedNormal;
    int facet;
    ASSERT_TRUE(diamondExit(stone(), p, d, t, n, facet));
    for (int other = 0; other < kDiamondPlanes; ++other) {
      if (other == facet || !diamondExitThrough(stone(), p, d, other, tried_t, triedNormal)) continue;
      ADD_FAILURE() << "ray " << i << " accepted on facet " << other << ", leaves by " << facet;
    }
    if (facet == kGirdleFacet) continue;
    ++tried;
    if (!diamondExitThrough(stone(), p, d, facet, tried_t, triedNormal)) continue;
    ++accepted;
    ASSERT_EQ(tried_t, t);
    ASSERT_EQ(triedNormal, n);
  }
  EXPECT_GT(accepted, tried * 99 / 100);  // only a margin of 1e-5 of the radius round each edge falls back
}

// --- The proxy hull.

float stoneVolume(const DiamondGeometry& g) {
  // Slices along z; each slice is star-shaped about the axis, so its area is the integral of r(θ)²/2.
  constexpr int kSlices = 1000, kAngles = 1024;
  const double z0 = -g.culetDepth, z1 = g.tableHeight;
  double volume = 0.0;
  for (int i = 0; i < kSlices; ++i) {
    const double z = z0 + (i + 0.5) * (z1 - z0) / kSlices;
    double area = 0.0;
    for (int j = 0; j < kAngles; ++j) {
      const double a = (j + 0.5) * glm::two_pi<double>() / kAngles;
      double r = g.girdleRadius;
      for (const glm::vec4& p : g.planes) {
        const double outward = p.x * std::cos(a) + p.y * std::sin(a), room = p.w - p.z * z;
        if (outward > 1e-9) r = std::min(r, room / outward);
        else if (room < 0.0) r = 0.0;
      }
      area += 0.5 * std::max(r, 0.0) * std::max(r, 0.0) * glm::two_pi<double>() / kAngles;
    }
    volume += area * (z1 - z0) / kSlices;
  }
  return float(volume);
}

TEST(DiamondHull, FewTrianglesClosedAndConvex) {
  const std::vector<glm::vec3> tris = diamondHullTriangles(stone());
  ASSERT_EQ(tris.size() % 3, 0u);
  EXPECT_LT(tris.size() / 3, 100u);
  std::cout << "[ DiamondHull ] " << tris.size() / 3 << " triangles\n";
  // Closed: every directed edge appears once, its reverse once.
  auto key = [](glm::vec3 p) {
    return std::make_tuple(std::lround(p.x * 1e3), std::lround(p.y * 1e3), std::lround(p.z * 1e3));
  };
  std::map<std::pair<decltype(key({})), decltype(key({}))>, int> edges;
  for (size_t i = 0; i < tris.size(); i += 3)
    for (int e = 0; e < 3; ++e) ++edges[{key(tris[i + e]), key(tris[i + (e + 1) % 3])}];
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u);
  }
  // Convex and counter-clockwise from outside: every vertex behind every face, every face facing away.
  for (size_t i = 0; i < tris.size(); i += 3) {
    const glm::vec3 n = glm::normalize(glm::cross(tris[i + 1] - tris[i], tris[i + 2] - tris[i]));
    EXPECT_GT(glm::dot(n, tris[i] + tris[i + 1] + tris[i + 2]), 0.0f);
    for (const glm::vec3& p : tris) ASSERT_LE(glm::dot(n, p - tris[i]), kLength);
  }
}

TEST(DiamondHull, HoldsTheWholeStoneTightly) {
  const DiamondGeometry& g = stone();
  const std::vector<glm::vec3> tris = diamondHullTriangles(g);
  std::vector<glm::vec4> faces;
  for (size_t i = 0; i < tris.size(); i += 3) {
    const glm::vec3 n = glm::normalize(glm::cross(tris[i + 1] - tris[i], tris[i + 2] - tris[i]));
    faces.emplace_back(n, glm::dot(n, tris[i]));
  }
  auto inside = [&](glm::vec3 p) {
    for (const glm::vec4& f : faces)
      if (planeTerm(f, p) > kLength) return false;
    return true;
  };
  for (int f = 0; f < kDiamondPlanes; ++f)
    for (const glm::vec3& c : diamondFacetCorners(g, f)) EXPECT_TRUE(inside(c)) << g.names[f];
  float top = g.girdleHalfHeight;
  for (const glm::vec3& p : g.vertices.girdleTopStar) top = glm::max(top, p.z);
  for (int j = 0; j < 1440; ++j) {
    const float a = j * glm::two_pi<float>() / 1440.0f;
    for (float z : {-g.girdleHalfHeight, 0.0f, top})
      ASSERT_TRUE(inside({g.girdleRadius * std::cos(a), g.girdleRadius * std::sin(a), z})) << a << " " << z;
  }
  uint32_t seed = 0;
  for (int i = 0; i < 2000; ++i, ++seed) ASSERT_TRUE(inside(randomInside(seed)));
  // Volume: the divergence theorem over the triangles, against the stone sliced numerically.
  float hull = 0.0f;
  for (size_t i = 0; i < tris.size(); i += 3) hull += glm::dot(tris[i], glm::cross(tris[i + 1], tris[i + 2])) / 6.0f;
  const float ratio = hull / stoneVolume(g);
  std::cout << "[ DiamondHull ] volume / stone volume: " << ratio << "\n";
  EXPECT_GE(ratio, 1.0f);
  EXPECT_LE(ratio, 1.05f);
}

// --- Rays.

float marchedExit(glm::vec3 p, glm::vec3 d) {
  const float step = 1e-3f * kDiameter;
  float t = 0.0f;
  while (diamondSdf(stone(), p + t * d) <= 0.0f) t += step;
  float lo = glm::max(t - step, 0.0f), hi = t;
  for (int i = 0; i < 40; ++i) {
    const float mid = 0.5f * (lo + hi);
    (diamondSdf(stone(), p + mid * d) > 0.0f ? hi : lo) = mid;
  }
  return hi;
}

TEST(DiamondRays, ExitMatchesMarchingAndNamesTheFacet) {
  uint32_t seed = 0;
  int agree = 0, facetsChecked = 0;
  constexpr int kRays = test::trials(4000);
  for (uint32_t i = 0; i < kRays; ++i, ++seed) {
    const glm::vec3 p = randomInside(seed), d = randomDirection(i, 61u);
    float t;
    glm::vec3 n;
    int facet;
    ASSERT_TRUE(diamondExit(stone(), p, d, t, n, facet));
    ASSERT_GT(glm::dot(n, d), 0.0f);
    ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
    if (std::fabs(t - marchedExit(p, d)) < 1e-3f * kDiameter) ++agree;
    const glm::vec3 q = p + t * d;
    if (diamondEdgeDistance(stone(), q) < 1e-3f * kDiameter) continue;  // a hair from an edge: either facet
    ++facetsChecked;
    int expected;
    diamondNormal(stone(), q, expected);
    ASSERT_EQ(facet, expected);
  }
  EXPECT_EQ(agree, kRays);
  EXPECT_GT(facetsChecked, kRays * 3 / 4);  // the small crown facets meet at shallow angles: wide edge zones
}

TEST(DiamondRays, EnterFromOutsideMatchesMarching) {
  uint32_t seed = 0;
  constexpr uint32_t kRays = test::trials(2000);
  for (uint32_t i = 0; i < kRays; ++i, ++seed) {
    const glm::vec3 target = randomInside(seed);
    const glm::vec3 ro = randomDirection(i, 67u) * (1.5f * kDiameter);
    const glm::vec3 rd = glm::normalize(target - ro);
    float t;
    glm::vec3 n;
    int facet;
    ASSERT_TRUE(diamondEnter(stone(), ro, rd, t, n, facet));
    ASSERT_LT(glm::dot(n, rd), 0.0f);
    // Marching backwards from the inside target finds the same front surface.
    const float back = marchedExit(target, -rd);
    ASSERT_NEAR(t, glm::distance(ro, target) - back, 1e-3f * kDiameter);
    const glm::vec3 q = ro + t * rd;
    if (diamondEdgeDistance(stone(), q) < 1e-3f * kDiameter) continue;
    int expected;
    diamondNormal(stone(), q, expected);
    ASSERT_EQ(facet, expected);
  }
}

TEST(DiamondRays, EnterMissesRaysBesideOrFromInside) {
  float t;
  glm::vec3 n;
  int facet;
  EXPECT_FALSE(diamondEnter(stone(), {0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}, t, n, facet));  // from inside
  EXPECT_FALSE(diamondEnter(stone(), {0.0f, 0.0f, 500.0f}, {0.0f, 0.0f, 1.0f}, t, n, facet));  // pointing away
  EXPECT_FALSE(diamondEnter(stone(), {201.0f, 0.0f, 500.0f}, {0.0f, 0.0f, -1.0f}, t, n, facet));  // past the girdle
  EXPECT_FALSE(diamondEnter(stone(), {-500.0f, 0.0f, 80.0f}, {1.0f, 0.0f, 0.0f}, t, n, facet));  // over the table
  ASSERT_TRUE(diamondEnter(stone(), {0.0f, 0.0f, 500.0f}, {0.0f, 0.0f, -1.0f}, t, n, facet));
  EXPECT_EQ(facet, 0);
  EXPECT_NEAR(t, 500.0f - stone().tableHeight, 1e-3f);
  ASSERT_TRUE(diamondEnter(stone(), {-500.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, t, n, facet));
  EXPECT_EQ(facet, kGirdleFacet);
  EXPECT_NEAR(t, 300.0f, 1e-3f);
  EXPECT_NEAR(glm::distance(n, glm::vec3(-1.0f, 0.0f, 0.0f)), 0.0f, 1e-6f);
}

// --- The interior walk.

// Light from a random direction outside, refracted in through the front facet.
DiamondWalk enteringWalk(uint32_t i, int maxBounces, bool physical, float eta = kEta) {
  uint32_t seed = i * 7u;
  const glm::vec3 target = randomInside(seed);
  const glm::vec3 ro = randomDirection(i, 71u) * (1.5f * kDiameter);
  const glm::vec3 rd = glm::normalize(target - ro);
  float t;
  glm::vec3 n;
  int facet;
  if (!diamondEnter(stone(), ro, rd, t, n, facet)) ADD_FAILURE() << "ray " << i << " missed the stone";
  const glm::vec3 d = *refractDir(rd, n, eta);  // air to diamond never totally reflects
  const float entering = physical ? 1.0f - fresnelDielectric(-glm::dot(rd, n), eta) : 1.0f;
  DiamondWalk w = diamondWalkStart(ro + t * rd, d, entering, maxBounces);
  w.facet = facet;
  return w;
}

struct WalkCase {
  int maxBounces;
  bool physical;
};

class Walk : public ::testing::TestWithParam<WalkCase> {};

TEST_P(Walk, EndsWithinTheBudgetAndConservesLight) {
  const auto [maxBounces, physical] = GetParam();
  for (uint32_t i = 0; i < 1000; ++i) {
    DiamondWalk w = enteringWalk(i, maxBounces, physical);
    const float entering = w.throughput;
    float left = 0.0f;
    int steps = 0, exits = 0;
    glm::vec3 exitDir;
    float exitWeight;
    while (diamondStep(stone(), w, kEta, physical, exitDir, exitWeight)) {
      ASSERT_LE(++steps, maxBounces + 1);
      ASSERT_NEAR(glm::length(exitDir), 1.0f, 1e-4f);  // safe to look up, even at zero weight
      ASSERT_GE(exitWeight, 0.0f);
      left += exitWeight;
      if (exitWeight > 0.0f) ++exits;
    }
    ASSERT_NE(w.status, kWalkMissed) << "ray " << i;
    ASSERT_NE(w.status, kWalking);
    ASSERT_LE(w.bounces, maxBounces);
    ASSERT_NEAR(left + w.throughput, entering, 1e-4f) << "ray " << i;
    if (!physical) {  // seed mode: the light leaves whole, once, or stays in when the budget runs out
      ASSERT_EQ(exits, w.status == kWalkDone ? 1 : 0);
      ASSERT_EQ(w.throughput, w.status == kWalkDone ? 0.0f : entering);
    }
    ASSERT_FALSE(diamondStep(stone(), w, kEta, physical, exitDir, exitWeight));  // stays ended
    ASSERT_EQ(exitWeight, 0.0f);
  }
}

TEST_P(Walk, ReflectsTotallyExactlyBeyondTheCriticalAngle) {
  const auto [maxBounces, physical] = GetParam();
  const float critical = std::asin(1.0f / kEta);
  int total = 0, partial = 0;
  for (uint32_t i = 0; i < 500; ++i) {
    DiamondWalk w = enteringWalk(i, maxBounces, physical);
    for (;;) {
      float t;
      glm::vec3 n, exitDir;
      int facet;
      ASSERT_TRUE(diamondExit(stone(), w.p, w.d, t, n, facet));
      const float incidence = std::acos(glm::clamp(glm::dot(w.d, n), -1.0f, 1.0f));
      const float before = w.throughput;
      float exitWeight;
      const bool more = diamondStep(stone(), w, kEta, physical, exitDir, exitWeight);
      if (std::fabs(incidence - critical) > 1e-4f) {
        if (incidence > critical) {
          ++total;
          ASSERT_EQ(exitWeight, 0.0f) << glm::degrees(incidence);
        } else {
          ++partial;
          ASSERT_GT(exitWeight, 0.0f) << glm::degrees(incidence);
          if (physical) {
            ASSERT_NEAR(exitWeight, before * (1.0f - fresnelDielectric(std::cos(incidence), 1.0f / kEta)), 1e-5f);
          }
          ASSERT_NEAR(glm::dot(exitDir, n), std::sqrt(1.0f - glm::pow(kEta * std::sin(incidence), 2.0f)), 1e-3f);
        }
      }
      if (!more || w.status != kWalking) break;
    }
  }
  EXPECT_GT(total, 100);
  EXPECT_GT(partial, 100);
}

INSTANTIATE_TEST_SUITE_P(Budgets, Walk,
                         ::testing::Values(WalkCase{1, false}, WalkCase{6, false}, WalkCase{32, false},
                                           WalkCase{1, true}, WalkCase{6, true}, WalkCase{32, true}),
                         [](const ::testing::TestParamInfo<WalkCase>& test) {
                           return std::string(test.param.physical ? "Physical" : "Seed") +
                                  std::to_string(test.param.maxBounces);
                         });

// Following the previous wavelength's route gives each leg the exit searching all 57 planes would.
TEST(DiamondWalk, FollowingTheLastWavelengthsRouteChangesNoLeg) {
  int legs = 0, followed = 0;
  for (uint32_t i = 0; i < 500; ++i) {
    glm::uvec2 route = kNoRoute;
    for (int k = 0; k < 16; ++k) {
      const float eta = cauchyIor(400.0f + 20.0f * float(k), kEta, 55.0f);
      DiamondWalk w = enteringWalk(i, 6, true, eta);
      w.route = route;
      for (;;) {
        const int leg = w.bounces, expected = routeFacet(w.route, leg);
        float t;
        glm::vec3 n, exitDir;
        int facet;
        float exitWeight;
        const bool exits = diamondExit(stone(), w.p, w.d, t, n, facet);
        const glm::vec3 searchedPoint = w.p + t * w.d;
        const bool more = diamondStep(stone(), w, eta, true, exitDir, exitWeight);
        ASSERT_EQ(w.status == kWalkMissed, !exits);
        if (!exits) break;
        ++legs;
        followed += expected == w.facet ? 1 : 0;
        ASSERT_EQ(w.facet, facet) << "ray " << i << " wavelength " << k << " leg " << leg;
        ASSERT_LT(glm::distance(w.p, searchedPoint), kLength) << "ray " << i << " wavelength " << k << " leg " << leg;
        ASSERT_EQ(routeFacet(w.route, leg), leg < kRouteLegs ? facet : -1);
        if (!more) break;
      }
      route = w.route;
    }
  }
  EXPECT_GT(followed, legs * 3 / 4);  // most legs leave where the last wavelength's did
  std::cout << followed << " of " << legs << " legs left by the last wavelength's facet\n";
}

TEST(DiamondWalk, CriticalAngleOfDiamond) {
  EXPECT_NEAR(glm::degrees(std::asin(1.0f / kEta)), 24.44f, 0.01f);
  // Just inside and just beyond it, at the table from below.
  for (float degrees : {24.3f, 24.6f}) {
    const float a = glm::radians(degrees);
    DiamondWalk w = diamondWalkStart({0.0f, 0.0f, 0.0f}, {std::sin(a), 0.0f, std::cos(a)}, 1.0f, 0);
    glm::vec3 exitDir;
    float exitWeight;
    const bool left = diamondStep(stone(), w, kEta, false, exitDir, exitWeight);
    EXPECT_EQ(w.facet, 0);
    EXPECT_EQ(left, degrees < 24.44f);
    EXPECT_EQ(w.status, degrees < 24.44f ? kWalkDone : kWalkExhausted);
  }
}

// Straight down through the table a ray meets a pavilion main at 40.75°, beyond the critical angle, reflects
// across to the opposite main at 57.75°, reflects again and climbs at 17° from the axis: under the critical
// angle at the table, so it leaves through the crown. This return of light is what the ideal cut is for.
TEST(DiamondWalk, VerticalRayThroughTheTableComesBackUp) {
  const DiamondGeometry& g = stone();
  for (float radius : {10.0f, 30.0f, 50.0f}) {
    DiamondWalk w = diamondWalkStart({radius, 0.0f, g.tableHeight}, {0.0f, 0.0f, -1.0f}, 1.0f, 6);
    glm::vec3 exitDir;
    float exitWeight;
    std::vector<int> facets;
    while (diamondStep(g, w, kEta, false, exitDir, exitWeight)) facets.push_back(w.facet);
    ASSERT_EQ(w.status, kWalkDone);
    EXPECT_EQ(w.bounces, 2);
    ASSERT_EQ(facets.size(), 3u);
    EXPECT_EQ(facets[0], 33);      // pavilion main 0, beneath
    EXPECT_EQ(facets[1], 33 + 4);  // the main opposite
    EXPECT_LE(facets[2], 32);      // out through the crown
    EXPECT_GT(exitDir.z, 0.9f);
  }
  // Over the whole table, most straight-down light comes back up in seed mode.
  int up = 0, rays = 0;
  for (uint32_t i = 0; i < 2000; ++i) {
    const glm::vec2 xy = glm::vec2(randomSigned(i, 73u)) * 0.5f * kTableRatio * g.girdleRadius;
    DiamondWalk w = diamondWalkStart({xy.x, xy.y, g.tableHeight}, {0.0f, 0.0f, -1.0f}, 1.0f, 6);
    glm::vec3 exitDir;
    float exitWeight;
    ++rays;
    while (diamondStep(g, w, kEta, false, exitDir, exitWeight))
      if (exitWeight > 0.0f && exitDir.z > 0.0f) ++up;
  }
  std::cout << "[ DiamondWalk ] straight-down table rays leaving upward: " << float(up) / rays << "\n";
  EXPECT_GT(up, rays * 9 / 10);
}

TEST(DiamondWalk, PhysicalModeSendsMostOfAVerticalRayBackUp) {
  const DiamondGeometry& g = stone();
  DiamondWalk w = diamondWalkStart({30.0f, 0.0f, g.tableHeight}, {0.0f, 0.0f, -1.0f}, 1.0f, 32);
  glm::vec3 exitDir;
  float exitWeight, up = 0.0f, down = 0.0f;
  while (diamondStep(g, w, kEta, true, exitDir, exitWeight)) (exitDir.z > 0.0f ? up : down) += exitWeight;
  // At the table the exact Fresnel reflectance is ((n - 1) / (n + 1))² ~ 17 % at normal-ish incidence.
  EXPECT_GT(up, 0.75f);
  EXPECT_LT(down, 0.2f);
  EXPECT_NEAR(up + down + w.throughput, 1.0f, 1e-4f);
}

TEST(DiamondWalk, BrokenDirectionIsMissed) {
  DiamondWalk w = diamondWalkStart({0.0f, 0.0f, 0.0f}, glm::vec3(0.0f), 1.0f, 6);
  glm::vec3 exitDir;
  float exitWeight;
  EXPECT_FALSE(diamondStep(stone(), w, kEta, true, exitDir, exitWeight));
  EXPECT_EQ(w.status, kWalkMissed);
  EXPECT_EQ(exitWeight, 0.0f);
  EXPECT_EQ(w.throughput, 1.0f);  // nothing left, nothing lost
}

TEST(DiamondShape, DispatchMatchesTheDiamondFunctions) {
  const ShapeDims s = diamondDims(kDiameter);
  uint32_t seed = 0;
  for (uint32_t i = 0; i < 200; ++i, ++seed) {
    const glm::vec3 p = randomInside(seed), d = randomDirection(i, 79u);
    EXPECT_EQ(shapeSdf(s, p), diamondSdf(stone(), p));
    float t1, t2;
    glm::vec3 n1, n2;
    int f1, f2;
    ASSERT_TRUE(shapeExit(s, p, d, t1, n1, f1));
    ASSERT_TRUE(diamondExit(stone(), p, d, t2, n2, f2));
    EXPECT_EQ(t1, t2);
    EXPECT_EQ(f1, f2);
    EXPECT_EQ(n1, n2);
  }
  EXPECT_EQ(shapeHalfExtent(s), glm::vec3(200.0f, 200.0f, stone().culetDepth));
}

}  // namespace
}  // namespace vitrine::glass
