// The glass scene's shapes (src/scenes/glass/shapes.h): distance fields, front hits, analytic back exits
// against brute-force marching, and the rotations.
#include "maths/hash.h"
#include "scenes/glass/diamond.h"
#include "scenes/glass/shapes.h"
#include "support/random_vectors.h"
#include "support/trials.h"

#include <glm/gtc/constants.hpp>
#include <glm/matrix.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace vitrine::glass {
namespace {

using test::randomDirection;
using test::randomSigned;

// The reference exit: small steps along d until the field turns positive, then bisection.
float marchedExit(const ShapeDims& s, glm::vec3 p, glm::vec3 d) {
  const float step = 1e-3f * shapeScale(s);
  float t = 0.0f;
  while (shapeSdf(s, p + t * d) <= 0.0f) t += step;
  float lo = glm::max(t - step, 0.0f), hi = t;
  for (int i = 0; i < 40; ++i) {
    const float mid = 0.5f * (lo + hi);
    (shapeSdf(s, p + mid * d) > 0.0f ? hi : lo) = mid;
  }
  return hi;
}

// The reference front hit: the same from outside, stepping until the field turns negative (or the ray is past).
float marchedEntry(const ShapeDims& s, glm::vec3 ro, glm::vec3 rd, float tMax) {
  const float step = 1e-3f * shapeScale(s);
  float t = 0.0f;
  while (shapeSdf(s, ro + t * rd) > 0.0f) {
    t += step;
    if (t > tMax) return -1.0f;
  }
  float lo = glm::max(t - step, 0.0f), hi = t;
  for (int i = 0; i < 40; ++i) {
    const float mid = 0.5f * (lo + hi);
    (shapeSdf(s, ro + mid * rd) > 0.0f ? lo : hi) = mid;
  }
  return hi;
}

glm::vec3 randomInside(const ShapeDims& s, uint32_t& i) {
  const glm::vec3 half = shapeHalfExtent(s);
  for (;; ++i) {
    const glm::vec3 p = randomSigned(i, 11u) * half;
    if (shapeSdf(s, p) < -1e-3f * shapeScale(s)) return p;
  }
}

glm::mat3 mirror(int axis) {
  glm::mat3 m(1.0f);
  m[axis][axis] = -1.0f;
  return m;
}
const glm::mat3 kSwapXY{0.0f, 1.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f};
// The mirror in the vertical plane at azimuth a (the diamond's D_8 mirrors).
glm::mat3 mirrorAt(float a) { return rotationZ(a) * mirror(1) * rotationZ(-a); }

struct ShapeCase {
  std::string name;
  ShapeDims dims;
  std::vector<glm::mat3> symmetries;  // maps the shape onto itself
};

// The original's presets (plate phase 0.7 rather than 0, so no accidental extra symmetry helps).
const std::vector<ShapeCase>& shapeCases() {
  static const std::vector<ShapeCase> cases = {
      {"Pill", pillDims({400.0f, 115.0f, 62.0f}, 100.0f), {mirror(0), mirror(1), mirror(2)}},
      {"SmoothPill", pillDims({400.0f, 115.0f, 62.0f}, 100.0f, true), {mirror(0), mirror(1), mirror(2)}},
      {"RoundedRectPill", pillDims({400.0f, 115.0f, 62.0f}, 30.0f), {mirror(0), mirror(1), mirror(2)}},
      {"SmoothRoundedRectPill", pillDims({400.0f, 115.0f, 62.0f}, 12.0f, true), {mirror(0), mirror(1), mirror(2)}},
      {"Prism", prismDims({393.0f, 149.0f, 117.0f}), {mirror(0), mirror(1)}},
      {"Cube", cubeDims(230.0f, 44.0f), {mirror(0), mirror(1), mirror(2), kSwapXY}},
      {"SmoothCube", cubeDims(230.0f, 44.0f, true), {mirror(0), mirror(1), mirror(2), kSwapXY}},
      {"Plate", plateDims({346.0f, 346.0f, 60.0f}, 10.5f, 17.0f, 535.0f, 0.7f), {kSwapXY}},
      {"SmoothPlate", plateDims({346.0f, 346.0f, 60.0f}, 10.5f, 17.0f, 535.0f, 0.7f, true), {kSwapXY}},
      {"Diamond",
       diamondDims(400.0f),
       {mirror(1), rotationZ(glm::quarter_pi<float>()), mirrorAt(glm::pi<float>() / 8.0f),
        mirrorAt(glm::pi<float>() * 0.75f)}},
  };
  return cases;
}

class Shape : public ::testing::TestWithParam<ShapeCase> {
 protected:
  const ShapeDims& dims() const { return GetParam().dims; }
  float scale() const { return shapeScale(dims()); }
};

TEST_P(Shape, NegativeAtTheCentre) { EXPECT_LT(shapeSdf(dims(), glm::vec3(0.0f)), -0.05f * scale()); }

TEST_P(Shape, PositiveOutsideTheBoundingBox) {
  const glm::vec3 half = shapeHalfExtent(dims());
  for (uint32_t i = 0; i < 2000; ++i) {
    glm::vec3 p = randomSigned(i, 3u) * half * 3.0f;
    const int axis = int(i % 3);  // push one coordinate out of the box
    p[axis] = (p[axis] < 0.0f ? -1.0f : 1.0f) * (half[axis] * 1.001f + std::fabs(p[axis]));
    ASSERT_GT(shapeSdf(dims(), p), 0.0f) << p.x << " " << p.y << " " << p.z;
  }
}

TEST_P(Shape, InsideLiesWithinTheHalfExtent) {
  const glm::vec3 half = shapeHalfExtent(dims());
  int inside = 0;
  for (uint32_t i = 0; i < 20000; ++i) {
    const glm::vec3 p = randomSigned(i, 5u) * half * 1.3f;
    if (shapeSdf(dims(), p) >= 0.0f) continue;
    ++inside;
    ASSERT_TRUE(glm::all(glm::lessThanEqual(glm::abs(p), half + 1e-4f * scale())));
  }
  EXPECT_GT(inside, 2000);  // the box is not loose
}

TEST_P(Shape, LipschitzBoundOnRandomPairs) {
  const glm::vec3 half = shapeHalfExtent(dims());
  for (uint32_t i = 0; i < 5000; ++i) {
    const glm::vec3 a = randomSigned(i, 7u) * half * 1.5f;
    const glm::vec3 b = a + randomSigned(i, 8u) * (i % 2 ? 0.02f : 0.5f) * scale();
    ASSERT_LE(std::fabs(shapeSdf(dims(), a) - shapeSdf(dims(), b)), glm::distance(a, b) * 1.0001f + 1e-3f);
  }
}

TEST_P(Shape, MirrorAndRotationSymmetries) {
  const glm::vec3 half = shapeHalfExtent(dims());
  for (const glm::mat3& m : GetParam().symmetries)
    for (uint32_t i = 0; i < 2000; ++i) {
      const glm::vec3 p = randomSigned(i, 9u) * half * 1.2f;
      ASSERT_NEAR(shapeSdf(dims(), m * p), shapeSdf(dims(), p), 2e-3f) << p.x << " " << p.y << " " << p.z;
    }
}

TEST_P(Shape, NormalsPointOutOfTheSurface) {
  uint32_t seed = 0;
  for (uint32_t i = 0; i < 500; ++i, ++seed) {
    const glm::vec3 p = randomInside(dims(), seed);
    const glm::vec3 d = randomDirection(i, 13u);
    const glm::vec3 q = p + marchedExit(dims(), p, d) * d;
    const glm::vec3 n = shapeNormal(dims(), q);
    ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    const float h = 2e-3f * scale();
    EXPECT_GT(shapeSdf(dims(), q + h * n), 0.0f);
    EXPECT_LT(shapeSdf(dims(), q - h * n), 0.0f);
  }
}

// The analytic back exit against brute-force marching from random inside points along random directions.
TEST_P(Shape, ExitAgreesWithMarching) {
  constexpr int kRays = test::trials(3000);
  int agree = 0;
  uint32_t seed = 0;
  for (uint32_t i = 0; i < kRays; ++i, ++seed) {
    const glm::vec3 p = randomInside(dims(), seed);
    const glm::vec3 d = randomDirection(i, 17u);
    float t;
    glm::vec3 n;
    int facet;
    if (shapeExit(dims(), p, d, t, n, facet) && std::fabs(t - marchedExit(dims(), p, d)) < 5e-3f * scale()) ++agree;
  }
  const double fraction = double(agree) / kRays;
  RecordProperty("agreeing", std::to_string(fraction));
  std::cout << "[ " << GetParam().name << " ] analytic exits agreeing with marching: " << fraction << "\n";
  EXPECT_GE(fraction, 0.98);
}

TEST_P(Shape, ExitNormalIsUnitAndOutward) {
  int outward = 0;
  uint32_t seed = 0;
  constexpr int kRays = 1000;
  for (uint32_t i = 0; i < kRays; ++i, ++seed) {
    const glm::vec3 p = randomInside(dims(), seed);
    const glm::vec3 d = randomDirection(i, 19u);
    float t;
    glm::vec3 n;
    int facet;
    ASSERT_TRUE(shapeExit(dims(), p, d, t, n, facet));
    ASSERT_GE(t, 0.0f);
    ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    if (glm::dot(n, d) > 0.0f && std::fabs(shapeSdf(dims(), p + t * d)) < 1e-3f * scale()) ++outward;
    if (GetParam().dims.kind == int(ShapeKind::Diamond)) {
      ASSERT_TRUE(facet >= 0 && facet <= kGirdleFacet);
    } else {
      ASSERT_EQ(facet, -1);
    }
  }
  EXPECT_GE(outward, kRays * 98 / 100);
}

// The sphere trace stops within kHitTolerance × scale of the surface, which along a grazing ray is further:
// so the hit must be that close to the surface and never past it, and t must match marching where not grazing.
TEST_P(Shape, EnterAgreesWithMarching) {
  const float reach = 2.0f * glm::length(shapeHalfExtent(dims())), tolerance = kHitTolerance * scale();
  uint32_t seed = 0;
  int hits = 0;
  constexpr int kRays = 500;
  for (uint32_t i = 0; i < kRays; ++i, ++seed) {
    const glm::vec3 target = randomInside(dims(), seed);
    const glm::vec3 ro = randomDirection(i, 23u) * reach;
    const glm::vec3 rd = glm::normalize(target - ro);
    float t;
    glm::vec3 n;
    int facet;
    const float reference = marchedEntry(dims(), ro, rd, 2.0f * reach);
    ASSERT_GT(reference, 0.0f);
    if (!shapeEnter(dims(), ro, rd, t, n, facet)) continue;
    ++hits;
    ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
    ASSERT_LT(glm::dot(n, rd), 0.0f);
    ASSERT_LT(std::fabs(shapeSdf(dims(), ro + t * rd)), tolerance);
    ASSERT_LT(t, reference + tolerance);
    if (glm::dot(n, rd) < -0.3f) {
      ASSERT_NEAR(t, reference, 5e-3f * scale());
    }
  }
  EXPECT_GE(hits, kRays * 98 / 100);
}

TEST_P(Shape, EnterMissesRaysPassingBeside) {
  const float radius = glm::length(shapeHalfExtent(dims()));
  for (uint32_t i = 0; i < 500; ++i) {
    const glm::vec3 d = randomDirection(i, 29u);
    // Any direction perpendicular to d, offset past the bounding sphere.
    const glm::vec3 side =
        glm::normalize(glm::cross(d, std::fabs(d.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
    const glm::vec3 ro = side * radius * 1.01f - d * 3.0f * radius;
    float t;
    glm::vec3 n;
    int facet;
    ASSERT_FALSE(shapeEnter(dims(), ro, d, t, n, facet));
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, Shape, ::testing::ValuesIn(shapeCases()),
                         [](const ::testing::TestParamInfo<ShapeCase>& test) { return test.param.name; });

// --- Exact distances on known points.

TEST(Pill, ExactDistances) {
  const ShapeDims s = pillDims({400.0f, 115.0f, 62.0f}, 100.0f);
  EXPECT_NEAR(shapeSdf(s, {0.0f, 0.0f, 0.0f}), -31.0f, 1e-4f);        // half the thickness
  EXPECT_NEAR(shapeSdf(s, {0.0f, 0.0f, 31.0f + 5.0f}), 5.0f, 1e-4f);  // above the face centre
  EXPECT_NEAR(shapeSdf(s, {200.0f + 7.0f, 0.0f, 0.0f}), 7.0f, 1e-4f);  // beyond the round end
  EXPECT_NEAR(shapeSdf(s, {0.0f, 57.5f + 3.0f, 0.0f}), 3.0f, 1e-4f);   // beside the straight side
  // The rim is a half-round of radius 31 about (y = 57.5 - 31, z = 0): 41 from its centre is 10 outside.
  const float c = 41.0f * std::sqrt(0.5f);
  EXPECT_NEAR(shapeSdf(s, {0.0f, 26.5f + c, c}), 10.0f, 1e-3f);
  // Beyond the round end's rim, diagonally in x and z.
  EXPECT_NEAR(shapeSdf(s, {142.5f + 57.5f - 31.0f + c, 0.0f, c}), 10.0f, 1e-3f);
}

TEST(Pill, RimRadiusClampsToHalfTheThickness) {
  const ShapeDims preset = pillDims({400.0f, 115.0f, 62.0f}, 100.0f),
                  clamped = pillDims({400.0f, 115.0f, 62.0f}, 57.5f);  // the outline's corners stop at H/2
  const ShapeDims sharper = pillDims({400.0f, 115.0f, 62.0f}, 10.0f);
  float differs = 0.0f;
  for (uint32_t i = 0; i < 2000; ++i) {
    const glm::vec3 p = randomSigned(i, 31u) * glm::vec3(220.0f, 70.0f, 45.0f);
    ASSERT_FLOAT_EQ(shapeSdf(preset, p), shapeSdf(clamped, p));
    differs = glm::max(differs, std::fabs(shapeSdf(sharper, p) - shapeSdf(preset, p)));
  }
  EXPECT_GT(differs, 1.0f);
}

TEST(Pill, SquircleRimAgreesOnTheFacesAndBulgesAtTheRim) {
  const ShapeDims round = pillDims({400.0f, 115.0f, 62.0f}, 100.0f),
                  squircle = pillDims({400.0f, 115.0f, 62.0f}, 100.0f, true);
  EXPECT_NEAR(shapeSdf(squircle, {0.0f, 0.0f, 36.0f}), 5.0f, 1e-4f);
  EXPECT_NEAR(shapeSdf(squircle, {0.0f, 62.5f, 0.0f}), 5.0f, 1e-4f);
  const float c = 31.0f * std::sqrt(0.5f);  // on the round rim, diagonally: inside the L4 rim
  EXPECT_NEAR(shapeSdf(round, {0.0f, 26.5f + c, c}), 0.0f, 1e-3f);
  EXPECT_LT(shapeSdf(squircle, {0.0f, 26.5f + c, c}), -1.0f);
  for (uint32_t i = 0; i < 2000; ++i) {  // the L4 norm never exceeds the L2 norm: the squircle holds the round pill
    const glm::vec3 p = randomSigned(i, 37u) * glm::vec3(220.0f, 70.0f, 45.0f);
    ASSERT_LE(shapeSdf(squircle, p), shapeSdf(round, p) + 1e-4f);
  }
}

// An edge below half the height makes the outline a rounded rectangle, not a stadium.
TEST(Pill, OutlineIsARoundedRectangleWhenTheEdgeIsBelowHalfTheHeight) {
  const ShapeDims s = pillDims({400.0f, 115.0f, 62.0f}, 30.0f);  // corners of 30 about (170, 27.5); rim 30
  const float q = std::sqrt(25.0f * 25.0f + 22.5f * 22.5f);
  EXPECT_NEAR(shapeSdf(s, {195.0f, 50.0f, 0.0f}), q - 30.0f, 1e-3f);  // a stadium would be 15 away here
  EXPECT_LT(shapeSdf(s, {185.0f, 45.0f, 0.0f}), -5.0f);                // outside a stadium, inside this pill
  EXPECT_NEAR(shapeSdf(s, {205.0f, 0.0f, 0.0f}), 5.0f, 1e-4f);          // the flat end
  EXPECT_NEAR(shapeSdf(pillDims({400.0f, 115.0f, 62.0f}, 80.0f), {195.0f, 50.0f, 0.0f}),
              std::sqrt(52.5f * 52.5f + 50.0f * 50.0f) - 57.5f, 1e-3f);  // at or above H/2: the stadium
}

// Smooth curvature: an L4 rim whose radius is compensated so it cuts the corner's diagonal as much as a
// circle of the edge radius does; it agrees with the round rim on the faces and holds it elsewhere.
TEST(Squircle, CompensationIsTheDiagonalCutRatio) {
  EXPECT_NEAR(kSquircleCompensation, (1.0 - std::sqrt(0.5)) / (1.0 - std::pow(2.0, -0.25)), 1e-6);
  EXPECT_NEAR(lengthL4(glm::vec2(1.0f, 1.0f)), std::pow(2.0f, 0.25f), 1e-6f);
  EXPECT_NEAR(lengthL4(glm::vec3(3.0f, 0.0f, 0.0f)), 3.0f, 1e-6f);
  EXPECT_FLOAT_EQ(rimRadius(20.0f, 100.0f, true), 20.0f * kSquircleCompensation);
  EXPECT_FLOAT_EQ(rimRadius(20.0f, 100.0f, false), 20.0f);
  EXPECT_FLOAT_EQ(rimRadius(100.0f, 31.0f, true), 31.0f);
}

TEST(Squircle, CubeRimCutsTheCornerLikeTheRoundRim) {
  const ShapeDims round = cubeDims(230.0f, 20.0f), smooth = cubeDims(230.0f, 20.0f, true);
  // The round rim's 45-degree point on the edge between the +x and +y faces, half way up.
  const float c = 95.0f + 20.0f * std::sqrt(0.5f);
  EXPECT_NEAR(shapeSdf(round, {c, c, 0.0f}), 0.0f, 1e-3f);
  EXPECT_NEAR(shapeSdf(smooth, {c, c, 0.0f}), 0.0f, 1e-3f);
  const float r = 20.0f * kSquircleCompensation;  // the smooth rim's own 45-degree point, from its centre
  EXPECT_NEAR(shapeSdf(smooth, glm::vec3(115.0f - r + r * std::pow(2.0f, -0.25f)) * glm::vec3(1, 1, 0)), 0.0f, 1e-3f);
  EXPECT_NEAR(shapeSdf(smooth, {0.0f, 0.0f, 120.0f}), 5.0f, 1e-4f);  // the faces are where they were
  EXPECT_NEAR(shapeSdf(smooth, {121.0f, 10.0f, -30.0f}), 6.0f, 1e-4f);
}

TEST(Squircle, RimsCurveFromZeroWhereTheyMeetTheFaces) {
  // Along the rim's section (x, y) = (115 - R + u, 115 - R + v), the L4 profile leaves the face y = 115 as
  // v = R(1 - (u/R)^4)^(1/4): a drop of about u^4/(4 R^3), where a circle drops u^2/(2 R) at once.
  const ShapeDims smooth = cubeDims(230.0f, 44.0f, true);
  const float r = 44.0f * kSquircleCompensation, inner = 115.0f - r;
  for (float u : {0.1f, 0.2f, 0.3f}) {
    const float v = r * std::pow(1.0f - std::pow(u, 4.0f), 0.25f);
    EXPECT_NEAR(shapeSdf(smooth, {inner + u * r, inner + v, 0.0f}), 0.0f, 2e-3f) << u;
    EXPECT_LT(r - v, 0.25f * u * u * r) << "flatter than a circle of the same radius near the face, u = " << u;
  }
}

TEST(Squircle, PlateAndPillRimsUseTheCompensatedRadius) {
  const ShapeDims plate = plateDims({346.0f, 346.0f, 60.0f}, 10.5f, 0.0f, 535.0f, 0.0f, true);
  const glm::vec3 p{100.0f, 180.0f, 27.0f};
  EXPECT_NEAR(shapeSdf(plate, p), sdRoundedBox(p, {173.0f, 173.0f, 30.0f}, 10.5f * kSquircleCompensation, true), 1e-4f);
  const ShapeDims pill = pillDims({400.0f, 115.0f, 62.0f}, 12.0f, true);  // rim 22.1, outline corners 12
  const float r = 12.0f * kSquircleCompensation, s = r * std::pow(2.0f, -0.25f);
  EXPECT_NEAR(shapeSdf(pill, {0.0f, 57.5f - r + s, 31.0f - r + s}), 0.0f, 1e-3f);
}

TEST(Prism, ExactDistances) {
  const ShapeDims s = prismDims({393.0f, 149.0f, 117.0f});
  const float b = 74.5f, h = 117.0f;
  EXPECT_NEAR(shapeSdf(s, {0.0f, 0.0f, h / 2 + 5.0f}), 5.0f, 1e-4f);    // above the apex edge
  EXPECT_NEAR(shapeSdf(s, {30.0f, 10.0f, -h / 2 - 4.0f}), 4.0f, 1e-4f);  // below the base
  EXPECT_NEAR(shapeSdf(s, {196.5f + 6.0f, 0.0f, -20.0f}), 6.0f, 1e-4f);  // beyond an end cap
  const glm::vec2 slantNormal = glm::normalize(glm::vec2(h, b));          // the right slant, in YZ
  const glm::vec2 onSlant{b / 2, 0.0f};                                   // its midpoint
  const glm::vec2 out = onSlant + 3.0f * slantNormal;
  EXPECT_NEAR(shapeSdf(s, {50.0f, out.x, out.y}), 3.0f, 1e-4f);
  EXPECT_NEAR(shapeSdf(s, {50.0f, -out.x, out.y}), 3.0f, 1e-4f);
  // The incircle: radius area / semi-perimeter, centred on the axis that far above the base.
  const float inradius = b * h / (b + std::sqrt(b * b + h * h));
  EXPECT_NEAR(shapeSdf(s, {0.0f, 0.0f, -h / 2 + inradius}), -inradius, 1e-3f);
  EXPECT_NEAR(shapeSdf(s, {0.0f, b + 2.0f, -h / 2 - 2.0f}), std::sqrt(8.0f), 1e-3f);  // past a base corner
}

TEST(Cube, ExactDistances) {
  const ShapeDims s = cubeDims(230.0f, 44.0f);
  EXPECT_NEAR(shapeSdf(s, {115.0f + 3.0f, 20.0f, -30.0f}), 3.0f, 1e-4f);
  EXPECT_NEAR(shapeSdf(s, {0.0f, 0.0f, 0.0f}), -115.0f, 1e-4f);
  const glm::vec3 corner = glm::vec3(115.0f - 44.0f);  // the corner sphere's centre
  EXPECT_NEAR(shapeSdf(s, corner + (44.0f + 5.0f) * glm::normalize(glm::vec3(1.0f))), 5.0f, 1e-3f);
  EXPECT_NEAR(shapeSdf(s, -corner + 44.0f * glm::normalize(glm::vec3(-1.0f, -2.0f, -3.0f))), 0.0f, 1e-3f);
}

TEST(Cube, EdgeClampsToHalfTheSide) {
  const ShapeDims ball = cubeDims(230.0f, 1000.0f);  // rounding clamps to 115: a ball
  for (uint32_t i = 0; i < 1000; ++i) {
    const glm::vec3 p = randomSigned(i, 41u) * 200.0f;
    ASSERT_NEAR(shapeSdf(ball, p), glm::length(p) - 115.0f, 1e-3f);
  }
}

TEST(Plate, FlatPlateIsARoundedBox) {
  const ShapeDims s = plateDims({346.0f, 346.0f, 60.0f}, 10.5f, 0.0f, 535.0f, 0.7f);
  EXPECT_FLOAT_EQ(plateLipschitz(s.wave), 1.0f);
  for (uint32_t i = 0; i < 1000; ++i) {
    const glm::vec3 p = randomSigned(i, 43u) * 250.0f;
    ASSERT_NEAR(shapeSdf(s, p), sdRoundedBox(p, {173.0f, 173.0f, 30.0f}, 10.5f), 1e-4f);
  }
}

TEST(Plate, BothFacesRideTheMidSurface) {
  const ShapeDims s = plateDims({346.0f, 346.0f, 60.0f}, 10.5f, 17.0f, 535.0f, 0.7f);
  for (uint32_t i = 0; i < 200; ++i) {
    const glm::vec2 xy = glm::vec2(randomSigned(i, 47u)) * 150.0f;  // away from the rounded rim
    const float h = plateHeight(xy, s.wave);
    for (float side : {1.0f, -1.0f}) {  // bisect the face along z: uniform thickness measured along z
      float lo = h, hi = h + side * 60.0f;
      for (int k = 0; k < 40; ++k) {
        const float mid = 0.5f * (lo + hi);
        (shapeSdf(s, {xy.x, xy.y, mid}) < 0.0f ? lo : hi) = mid;
      }
      ASSERT_NEAR(lo, h + side * 30.0f, 1e-3f);
    }
  }
}

TEST(Plate, DistanceBoundFactorAndHalfExtent) {
  const ShapeDims s = plateDims({346.0f, 346.0f, 60.0f}, 10.5f, 17.0f, 535.0f, 0.7f);
  const float slope = 17.0f * glm::two_pi<float>() / 535.0f;
  EXPECT_NEAR(plateLipschitz(s.wave), std::sqrt(1.0f + slope * slope / 2 + slope * std::sqrt(1.0f + slope * slope / 4)),
              1e-6f);
  EXPECT_NEAR(plateLipschitz(s.wave), 1.105f, 0.002f);
  EXPECT_EQ(shapeHalfExtent(s), glm::vec3(173.0f, 173.0f, 30.0f + 17.0f));
  // The wave's own gradient against a finite difference.
  for (uint32_t i = 0; i < 100; ++i) {
    const glm::vec2 xy = glm::vec2(randomSigned(i, 53u)) * 170.0f;
    const glm::vec2 g = plateSlope(xy, s.wave);
    const float e = 1e-2f;
    EXPECT_NEAR(g.x, (plateHeight(xy + glm::vec2(e, 0), s.wave) - plateHeight(xy - glm::vec2(e, 0), s.wave)) / (2 * e),
                1e-3f);
    EXPECT_NEAR(g.y, (plateHeight(xy + glm::vec2(0, e), s.wave) - plateHeight(xy - glm::vec2(0, e), s.wave)) / (2 * e),
                1e-3f);
  }
}

// Refracted rays stay within the critical cone of the faces; there the wavy-face exit is all but exact.
TEST(Plate, ExitsSteeperThanGrazingAllAgree) {
  const ShapeDims s = plateDims({346.0f, 346.0f, 60.0f}, 10.5f, 17.0f, 535.0f, 0.7f);
  uint32_t seed = 0;
  int tested = 0;
  for (uint32_t i = 0; tested < 2000; ++i, ++seed) {
    const glm::vec3 d = randomDirection(i, 59u);
    if (std::fabs(d.z) < 0.5f) continue;
    const glm::vec3 p = randomInside(s, seed);
    float t;
    glm::vec3 n;
    int facet;
    ASSERT_TRUE(shapeExit(s, p, d, t, n, facet));
    ASSERT_NEAR(t, marchedExit(s, p, d), 1e-3f * shapeScale(s));
    ++tested;
  }
}

TEST(Shapes, PrismExitNormalsAreTheFacePlanes) {
  const ShapeDims s = prismDims({393.0f, 149.0f, 117.0f});
  const std::vector<glm::vec3> normals = {{1, 0, 0},
                                          {-1, 0, 0},
                                          {0, 0, -1},
                                          glm::normalize(glm::vec3(0, 117, 74.5f)),
                                          glm::normalize(glm::vec3(0, -117, 74.5f))};
  float t;
  glm::vec3 n;
  int facet;
  const std::vector<glm::vec3> directions = {{1, 0, 0}, {-1, 0, 0}, {0, 0, -1}, normals[3], normals[4]};
  for (size_t i = 0; i < directions.size(); ++i) {
    ASSERT_TRUE(shapeExit(s, {0.0f, 0.0f, -10.0f}, directions[i], t, n, facet));
    EXPECT_NEAR(glm::distance(n, normals[i]), 0.0f, 1e-6f) << i;
    EXPECT_EQ(facet, -1);
  }
}

// --- Rotations.

struct RotationCase {
  std::string name;
  std::function<glm::mat3(float)> rotation;
};

const std::vector<RotationCase>& rotationCases() {
  static const std::vector<RotationCase> cases = {
      {"Cube", cubeRotation},
      {"Plate", plateRotation},
      {"DiamondTop", [](float t) { return diamondRotation(DiamondView::Top, t); }},
      {"DiamondSide", [](float t) { return diamondRotation(DiamondView::Side, t); }},
      {"DiamondBottom", [](float t) { return diamondRotation(DiamondView::Bottom, t); }},
      {"DiamondFree", [](float t) { return diamondRotation(DiamondView::Free, t); }},
  };
  return cases;
}

class Rotation : public ::testing::TestWithParam<RotationCase> {};

TEST_P(Rotation, OrthonormalWithDeterminantOne) {
  for (float t = 0.0f; t < 600.0f; t += 0.37f) {
    const glm::mat3 r = GetParam().rotation(t);
    const glm::mat3 identity = glm::transpose(r) * r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) ASSERT_NEAR(identity[i][j], i == j ? 1.0f : 0.0f, 1e-5f) << "t = " << t;
    ASSERT_NEAR(glm::determinant(r), 1.0f, 1e-5f) << "t = " << t;
  }
}

TEST_P(Rotation, ContinuousInTime) {
  constexpr float dt = 1e-3f;
  for (float t = 0.0f; t < 120.0f; t += 0.25f) {
    const glm::mat3 a = GetParam().rotation(t), b = GetParam().rotation(t + dt);
    for (int i = 0; i < 3; ++i) ASSERT_LT(glm::length(a[i] - b[i]), 2.0f * dt) << "t = " << t;  // under 2 rad/s
  }
}

TEST_P(Rotation, SlowAndGentle) {
  // Angular speed from the change over 0.1 s: never above 1 rad/s.
  for (float t = 0.0f; t < 120.0f; t += 0.5f) {
    const glm::mat3 delta = glm::transpose(GetParam().rotation(t)) * GetParam().rotation(t + 0.1f);
    const float angle = std::acos(glm::clamp(0.5f * (delta[0][0] + delta[1][1] + delta[2][2] - 1.0f), -1.0f, 1.0f));
    ASSERT_LT(angle / 0.1f, 1.0f) << "t = " << t;
  }
}

INSTANTIATE_TEST_SUITE_P(Animations, Rotation, ::testing::ValuesIn(rotationCases()),
                         [](const ::testing::TestParamInfo<RotationCase>& test) { return test.param.name; });

// The stone's table normal (object +z) seen in the world: R maps world to object, so its transpose.
glm::vec3 tableNormalInWorld(DiamondView view, float t) {
  return glm::transpose(diamondRotation(view, t)) * glm::vec3(0.0f, 0.0f, 1.0f);
}

TEST(DiamondViews, TopIsTheIdentityAtTimeZero) {
  const glm::mat3 r = diamondRotation(DiamondView::Top, 0.0f);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_FLOAT_EQ(r[i][j], i == j ? 1.0f : 0.0f);
}

TEST(DiamondViews, FixedViewsKeepTheTableWhereTheySay) {
  for (float t : {0.0f, 1.0f, 7.5f, 100.0f}) {
    EXPECT_NEAR(glm::distance(tableNormalInWorld(DiamondView::Top, t), glm::vec3(0, 0, 1)), 0.0f, 1e-5f) << t;
    EXPECT_NEAR(glm::distance(tableNormalInWorld(DiamondView::Side, t), glm::vec3(0, 1, 0)), 0.0f, 1e-5f) << t;
    EXPECT_NEAR(glm::distance(tableNormalInWorld(DiamondView::Bottom, t), glm::vec3(0, 0, -1)), 0.0f, 1e-5f) << t;
  }
  // Side: the camera (+z) looks at the girdle, neither table nor culet.
  EXPECT_NEAR(glm::dot(tableNormalInWorld(DiamondView::Side, 3.0f), glm::vec3(0, 0, 1)), 0.0f, 1e-5f);
}

TEST(DiamondViews, FreeViewTumblesAboutTwoAxes) {
  glm::vec3 lowest(1.0f), highest(-1.0f);
  for (float t = 0.0f; t < 120.0f; t += 0.5f) {
    const glm::vec3 n = tableNormalInWorld(DiamondView::Free, t);
    lowest = glm::min(lowest, n), highest = glm::max(highest, n);
  }
  // Over two minutes the table faces every way: each axis of its normal sweeps most of [-1, 1].
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(lowest[i], -0.8f);
    EXPECT_GT(highest[i], 0.8f);
  }
}

TEST(Animations, CubeTumblesAtTheChosenRates) {
  EXPECT_GE(kCubeSpinZ, 0.3f);
  EXPECT_LE(kCubeSpinX, 0.5f);
  // rz(a t)·rx(b t): at t = 1 the image of the x axis (which rx leaves alone) is turned by a about z.
  const glm::vec3 x = cubeRotation(1.0f) * glm::vec3(1, 0, 0);
  EXPECT_NEAR(x.x, std::cos(kCubeSpinZ), 1e-6f);
  EXPECT_NEAR(x.y, std::sin(kCubeSpinZ), 1e-6f);
  const glm::vec3 z = cubeRotation(1.0f) * glm::vec3(0, 0, 1);  // rx turns z by b toward -y; rz keeps z's z part
  EXPECT_NEAR(z.z, std::cos(kCubeSpinX), 1e-6f);
}

TEST(Animations, PlateWobblesGentlyAndItsWaveRolls) {
  float largest = 0.0f;
  for (float t = 0.0f; t < 200.0f; t += 0.1f) {
    const glm::mat3 r = plateRotation(t);
    largest = glm::max(largest, std::acos(glm::clamp(r[2][2], -1.0f, 1.0f)));  // the plate normal's tilt
  }
  EXPECT_GT(largest, 0.3f);
  EXPECT_LT(largest, kPlateWobbleAmplitude.x + kPlateWobbleAmplitude.y + 1e-3f);
  EXPECT_FLOAT_EQ(plateWavePhase(0.0f), 0.0f);
  EXPECT_NEAR(plateWavePhase(2.0f) - plateWavePhase(1.0f), kPlateWaveRate, 1e-6f);
}

}  // namespace
}  // namespace vitrine::glass
