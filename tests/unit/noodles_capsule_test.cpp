// The compute rasteriser's maths (scenes/noodles/capsule.h, mirrored by shaders/noodles/capsule.glsl):
// ray-capsule hits, the ordered depth bits, sample positions and the conservative screen box.
#include "scenes/noodles/camera.h"
#include "scenes/noodles/capsule.h"
#include "scenes/noodles/tube_view.h"
#include "support/trials.h"

#include <gtest/gtest.h>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace vitrine::noodles {
namespace {

// ------------------------------------------------------------------------------------ ray-capsule

TEST(NoodlesCapsule, RayHitsTheSideAtTheKnownDistance) {
  // Axis along x through the origin, radius 0.5; a ray down -z from z = 10 meets the top at z = 0.5.
  const float t = capsuleHit({0.3f, 0.0f, 10.0f}, {0.0f, 0.0f, -1.0f}, {-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f);
  EXPECT_NEAR(t, 9.5f, 1e-5f);
  // Off the axis by y = 0.3: the surface is at z = sqrt(0.25 - 0.09) = 0.4.
  const float offset =
      capsuleHit({0.3f, 0.3f, 10.0f}, {0.0f, 0.0f, -1.0f}, {-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f);
  EXPECT_NEAR(offset, 9.6f, 1e-5f);
}

TEST(NoodlesCapsule, RayHitsTheRoundEndBeyondTheSegment) {
  // Beyond the end at x = 1, 0.3 further: the end sphere's top is at z = sqrt(0.25 - 0.09) = 0.4.
  const float t = capsuleHit({1.3f, 0.0f, 10.0f}, {0.0f, 0.0f, -1.0f}, {-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f);
  EXPECT_NEAR(t, 9.6f, 1e-5f);
  // Looking straight along the axis from the far side of b: the cap's pole at x = 1.5.
  const float along =
      capsuleHit({5.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f);
  EXPECT_NEAR(along, 3.5f, 1e-5f);
  const float reverse =
      capsuleHit({-5.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 0.0f}, {1.0f, 0.0f, 0.0f}, 0.5f);
  EXPECT_NEAR(reverse, 3.5f, 1e-5f);
}

TEST(NoodlesCapsule, GrazingRaysMissJustOutsideAndHitJustInside) {
  const glm::vec3 a{-1.0f, 0.0f, 0.0f}, b{1.0f, 0.0f, 0.0f};
  EXPECT_EQ(capsuleHit({0.0f, 0.501f, 10.0f}, {0.0f, 0.0f, -1.0f}, a, b, 0.5f), kNoHit);
  EXPECT_GT(capsuleHit({0.0f, 0.499f, 10.0f}, {0.0f, 0.0f, -1.0f}, a, b, 0.5f), 0.0f);
  EXPECT_EQ(capsuleHit({1.501f, 0.0f, 10.0f}, {0.0f, 0.0f, -1.0f}, a, b, 0.5f), kNoHit);  // past the round end
  EXPECT_GT(capsuleHit({1.499f, 0.0f, 10.0f}, {0.0f, 0.0f, -1.0f}, a, b, 0.5f), 0.0f);
}

TEST(NoodlesCapsule, NothingBehindTheRayOrAroundItsStart) {
  const glm::vec3 a{-1.0f, 0.0f, 0.0f}, b{1.0f, 0.0f, 0.0f};
  EXPECT_EQ(capsuleHit({0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, 1.0f}, a, b, 0.5f), kNoHit);  // looking away
  EXPECT_EQ(capsuleHit({0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.0f}, a, b, 0.5f), kNoHit);  // from inside
}

TEST(NoodlesCapsule, ThinTubeFarAwayKeepsItsRadius) {
  // The write-up's radius 0.02 seen from 200 units: an unshifted quadratic loses the radius to
  // cancellation; the hit must still be within a part in 10^5 of 200 - 0.02 and the silhouette sharp.
  const glm::vec3 a{-0.03f, 0.0f, 0.0f}, b{0.03f, 0.0f, 0.0f};
  const float t = capsuleHit({0.0f, 0.0f, 200.0f}, {0.0f, 0.0f, -1.0f}, a, b, 0.02f);
  EXPECT_NEAR(t, 199.98f, 2e-3f);
  const glm::vec3 origin{0.0f, 0.0f, 200.0f};
  const auto towards = [&](float y) { return glm::normalize(glm::vec3(0.0f, y, 0.0f) - origin); };
  EXPECT_GT(capsuleHit(origin, towards(0.0195f), a, b, 0.02f), 0.0f);
  EXPECT_EQ(capsuleHit(origin, towards(0.0205f), a, b, 0.02f), kNoHit);
}

// The distance from a ray (t >= 0) to a segment, in double: the reference for the test below.
double raySegmentDistance(glm::dvec3 origin, glm::dvec3 direction, glm::dvec3 a, glm::dvec3 b) {
  const glm::dvec3 ba = b - a, oa = origin - a;
  const double baba = glm::dot(ba, ba), bad = glm::dot(ba, direction), baoa = glm::dot(ba, oa),
               doa = glm::dot(direction, oa);
  const double denominator = baba - bad * bad;  // |direction| = 1
  double s = denominator > 0.0 ? (baoa - bad * doa) / denominator : 0.0;
  s = std::clamp(s, 0.0, 1.0);
  const double t = std::max(glm::dot(a + s * ba - origin, direction), 0.0);
  s = std::clamp(glm::dot(origin + t * direction - a, ba) / baba, 0.0, 1.0);
  return glm::length(origin + t * direction - (a + s * ba));
}

// Long, thin segments (1,000 to 20,000 radii: the step and radius sliders reach them) against rays
// aimed within three radii of them: a ray passing within the radius hits and one passing outside it
// misses, whatever the segment's length, outside a band of 0.2 % of the radius either side.
TEST(NoodlesCapsule, LongThinSegmentsKeepTheirRadius) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), length(5.0f, 60.0f), radii(1000.0f, 20000.0f),
      offset(0.0f, 3.0f), angle(0.0f, 6.2831853f);
  int falseHits = 0, misses = 0, inside = 0, outside = 0;
  const int kTrials = test::trials(20000);
  for (int trial = 0; trial < kTrials; ++trial) {
    const glm::vec3 axis = glm::normalize(glm::vec3(unit(rng) - 0.5f, unit(rng) - 0.5f, unit(rng) - 0.5f));
    const float l = length(rng), r = l / radii(rng);
    const glm::vec3 a = glm::vec3(unit(rng), unit(rng), unit(rng)) - 0.5f, b = a + l * axis;
    const glm::vec3 origin = 0.5f * (a + b) + 5.0f * glm::normalize(glm::cross(axis, glm::vec3(0.3f, 1.0f, 0.2f)));
    const glm::vec3 across = glm::normalize(glm::cross(axis, glm::vec3(1.0f, 0.2f, 0.4f)));
    const glm::vec3 side = std::cos(angle(rng)) * across + std::sin(angle(rng)) * glm::cross(axis, across);
    const glm::vec3 target = glm::mix(a, b, unit(rng) * 1.1f - 0.05f) + offset(rng) * r * side;
    const glm::vec3 direction = glm::normalize(target - origin);
    const double distance = raySegmentDistance(origin, direction, a, b) / r;
    if (std::abs(distance - 1.0) < 0.002) continue;  // within float rounding of the surface: either way
    const bool hit = capsuleHit(origin, direction, a, b, r) != kNoHit;
    if (distance < 1.0) {
      ++inside;
      misses += !hit;
    } else {
      ++outside;
      falseHits += hit;
    }
  }
  EXPECT_GT(inside, kTrials / 5);
  EXPECT_GT(outside, kTrials / 5);
  EXPECT_EQ(falseHits, 0) << "of " << outside << " rays passing outside the radius";
  EXPECT_EQ(misses, 0) << "of " << inside << " rays passing inside the radius";
}

TEST(NoodlesCapsule, AlongSegmentClampsToTheEnds) {
  const glm::vec3 a{0.0f}, b{2.0f, 0.0f, 0.0f};
  EXPECT_FLOAT_EQ(alongSegment({0.5f, 3.0f, 0.0f}, a, b), 0.25f);
  EXPECT_FLOAT_EQ(alongSegment({-1.0f, 0.0f, 0.0f}, a, b), 0.0f);
  EXPECT_FLOAT_EQ(alongSegment({9.0f, 0.0f, 1.0f}, a, b), 1.0f);
}

TEST(NoodlesCapsule, InsideMeansShortOfTheSurface) {
  const glm::vec3 a{0.0f}, b{2.0f, 0.0f, 0.0f};
  EXPECT_TRUE(insideCapsule({1.0f, 0.4f, 0.0f}, a, b, 0.5f));
  EXPECT_TRUE(insideCapsule({-0.3f, 0.3f, 0.0f}, a, b, 0.5f));   // in the round end
  EXPECT_FALSE(insideCapsule({1.0f, 0.0f, 0.5f}, a, b, 0.5f));   // on the side: shared, not inside
  EXPECT_FALSE(insideCapsule({2.5f, 0.0f, 0.0f}, a, b, 0.5f));   // the tip of the round end
  EXPECT_FALSE(insideCapsule({-0.4f, 0.4f, 0.0f}, a, b, 0.5f));  // past the round end's corner
  // A hit on a capsule's end sphere that lies in the next capsule of a bent strand is inside it: the
  // case the raster pass drops when the near plane has cut the next capsule's own hit away.
  const glm::vec3 c{2.0f, 2.0f, 0.0f};
  const glm::vec3 direction = glm::normalize(glm::vec3(0.1f, 0.0f, -1.0f));
  const glm::vec3 origin = glm::vec3(2.0f, 0.45f, 0.0f) - 1.0f * direction;
  const float t = capsuleHit(origin, direction, a, b, 0.5f);
  ASSERT_GT(t, 0.0f);
  EXPECT_TRUE(insideCapsule(origin + t * direction, b, c, 0.5f));
}

// ---------------------------------------------------------------------------------- depth ordering

TEST(NoodlesCapsule, OrderedBitsSortLikeTheFloats) {
  const std::vector<float> sorted = {-std::numeric_limits<float>::infinity(),
                                     -1e30f,
                                     -2.0f,
                                     -1e-30f,
                                     0.0f,
                                     1e-30f,
                                     0.25f,
                                     0.2500001f,
                                     1.0f,
                                     3.5f,
                                     1e30f,
                                     std::numeric_limits<float>::infinity()};
  for (size_t i = 1; i < sorted.size(); ++i)
    EXPECT_LT(orderedBits(sorted[i - 1]), orderedBits(sorted[i])) << sorted[i - 1] << " vs " << sorted[i];
  std::mt19937 rng(4);
  std::uniform_real_distribution<float> distance(-100.0f, 100.0f);
  for (int i = 0; i < 10000; ++i) {
    const float x = distance(rng), y = distance(rng);
    EXPECT_EQ(x < y, orderedBits(x) < orderedBits(y));
  }
}

TEST(NoodlesCapsule, KeysOrderByDistanceThenSegmentAndEmptyIsLast) {
  EXPECT_LT(visibilityKey(1.0f, 900), visibilityKey(1.5f, 3));  // nearer wins whatever the segment
  EXPECT_LT(visibilityKey(2.0f, 3), visibilityKey(2.0f, 900));  // a tie goes to the lower segment
  EXPECT_LT(visibilityKey(1e30f, 0xfffffffeu), kEmptyKey);
}

// ------------------------------------------------------------------------------- screen and samples

TEST(NoodlesCapsule, FourSamplesFallOneInEachQuarterOfThePixel) {
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x) {
      const glm::vec2 p = cellSamplePosition({x, y}, 2);
      EXPECT_GE(p.x, 0.5f * float(x));  // inside cell (x, y) of the doubled grid
      EXPECT_LT(p.x, 0.5f * float(x + 1));
      EXPECT_GE(p.y, 0.5f * float(y));
      EXPECT_LT(p.y, 0.5f * float(y + 1));
    }
  EXPECT_EQ(cellSamplePosition({3, 7}, 1), glm::vec2(3.5f, 7.5f));
}

ScreenView testView(glm::vec3 eye, glm::vec3 target, glm::vec2 pixels) { return screenViewOf({eye, target}, pixels); }

TEST(NoodlesCapsule, RaysMatchTheProjectionTheTubesUsedToBeDrawnWith) {
  const glm::vec2 pixels{192.0f, 108.0f};
  const glm::vec3 eye{3.0f, -2.0f, 1.0f};
  const ScreenView view = testView(eye, {0.0f, 0.5f, 0.2f}, pixels);
  const glm::mat4 viewProjection =
      reverseZPerspective(kFieldOfViewY, pixels.x / pixels.y, kNearPlane) * lookAtZUp(eye, {0.0f, 0.5f, 0.2f});
  for (const glm::vec2 position : {glm::vec2(0.0f), glm::vec2(17.25f, 90.5f), glm::vec2(191.0f, 3.0f)}) {
    const glm::vec3 point = eye + 2.5f * rayThrough(view, position);
    const glm::vec4 clip = viewProjection * glm::vec4(point, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    EXPECT_NEAR((ndc.x + 1.0f) * 0.5f * pixels.x, position.x, 1e-3f);
    EXPECT_NEAR((ndc.y + 1.0f) * 0.5f * pixels.y, position.y, 1e-3f);
  }
}

// Every sample a brute-force cast hits lies in the capsule's cell box and in its row's hull columns,
// for random capsules near, far, crossing the near plane and off-screen; the box is not wildly loose
// either, and the hull columns take fewer cells than the box (far fewer for a thin diagonal tube).
TEST(NoodlesCapsule, CellBoxHoldsEveryHitSample) {
  const glm::uvec2 pixels{64, 36};
  const ScreenView view = testView({0.0f, -3.0f, 0.5f}, {0.0f, 0.0f, 0.0f}, glm::vec2(pixels));
  std::mt19937 rng(16);
  std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f), radius(0.01f, 0.3f), length(0.02f, 1.0f);
  int hitCapsules = 0, tightCapsules = 0;
  uint64_t boxCells = 0, hullCells = 0;
  const int kTrials = test::trials(300);
  for (int trial = 0; trial < kTrials; ++trial) {
    const glm::vec3 a{coordinate(rng), coordinate(rng) - 1.0f, coordinate(rng)};
    const glm::vec3 b = a + length(rng) * glm::normalize(glm::vec3(coordinate(rng), coordinate(rng), coordinate(rng)));
    const float r = radius(rng);
    for (const uint32_t samples : {1u, 2u}) {
      const EndBoxes ends = capsuleEndBoxes(view, a, b, r);
      const CellBox box = cellsOf(capsuleScreenBox(view, ends), samples, pixels);
      boxCells += box.count();
      int hits = 0;
      for (uint32_t y = 0; y < pixels.y * samples; ++y) {
        const float pixelsPerCell = 1.0f / float(samples);
        const glm::ivec2 columns =
            hullColumns(ends, float(y) * pixelsPerCell, float(y + 1) * pixelsPerCell, box, samples);
        if (!box.empty() && int(y) >= box.min.y && int(y) <= box.max.y && columns.x <= columns.y)
          hullCells += uint64_t(columns.y - columns.x + 1);
        for (uint32_t x = 0; x < pixels.x * samples; ++x) {
          const glm::vec3 direction = glm::normalize(rayThrough(view, cellSamplePosition({x, y}, samples)));
          const float t = capsuleHit(view.eye, direction, a, b, r);
          if (t == kNoHit || t * glm::dot(direction, view.forward) < view.nearPlane) continue;
          ++hits;
          EXPECT_TRUE(int(x) >= box.min.x && int(x) <= box.max.x && int(y) >= box.min.y && int(y) <= box.max.y)
              << "trial " << trial << " cell " << x << "," << y << " outside " << box.min.x << ".." << box.max.x << ", "
              << box.min.y << ".." << box.max.y;
          EXPECT_TRUE(int(x) >= columns.x && int(x) <= columns.y)
              << "trial " << trial << " cell " << x << "," << y << " outside the hull's " << columns.x << ".."
              << columns.y;
        }
      }
      if (hits > 0 && samples == 2) {
        ++hitCapsules;
        if (box.count() <= uint32_t(hits) * 8u + 64u) ++tightCapsules;
      }
    }
  }
  EXPECT_GT(hitCapsules, kTrials / 3);             // the trials do exercise visible capsules
  EXPECT_GT(tightCapsules, hitCapsules * 7 / 10);  // and the boxes are mostly close fits
  EXPECT_LT(hullCells * 100, boxCells * 97) << hullCells << " of " << boxCells << " cells";  // the hull cuts some

  // A thin diagonal tube across the view: its box is most of the image, its hull a sliver of it.
  const EndBoxes thin = capsuleEndBoxes(view, {-1.5f, 0.0f, -0.8f}, {1.5f, 0.0f, 1.8f}, 0.01f);
  const CellBox box = cellsOf(capsuleScreenBox(view, thin), 2, pixels);
  uint32_t reached = 0;
  for (int y = box.min.y; y <= box.max.y; ++y) {
    const glm::ivec2 columns = hullColumns(thin, 0.5f * float(y), 0.5f * float(y + 1), box, 2);
    reached += uint32_t(std::max(columns.y - columns.x + 1, 0));
  }
  EXPECT_GT(box.count(), 2000u);
  EXPECT_LT(reached * 5, box.count()) << reached << " of " << box.count() << " cells";
}

// Long thin segments from the middle of a 1920x1080 view to far off-screen, lying nearly along a row
// or a column: their far end boxes lie thousands of pixels out, where a band's t rounds the most, and
// every hit still lies in its row's columns, and on the capsule.
TEST(NoodlesCapsule, HullColumnsHoldTheHitsOfSegmentsReachingFarOffScreen) {
  const glm::uvec2 pixels{1920, 1080};
  const ScreenView view = testView({0.0f, -3.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, glm::vec2(pixels));
  std::mt19937 rng(29);
  std::uniform_real_distribution<float> near(-0.3f, 0.3f), slope(-0.01f, 0.01f), reach(5.0f, 60.0f),
      radius(0.005f, 0.03f);
  uint64_t hits = 0;
  const int kTrials = test::trials(60);
  for (int trial = 0; trial < kTrials; ++trial) {
    const glm::vec3 a{near(rng), near(rng), near(rng)};
    const float far = reach(rng) * (trial % 2 ? 1.0f : -1.0f);
    const glm::vec3 b =
        trial % 4 < 2 ? a + glm::vec3(far, 0.0f, far * slope(rng)) : a + glm::vec3(far * slope(rng), 0.0f, far);
    const float r = radius(rng);
    const EndBoxes ends = capsuleEndBoxes(view, a, b, r);
    const CellBox box = cellsOf(capsuleScreenBox(view, ends), 1, pixels);
    for (int y = box.min.y; y <= box.max.y; ++y) {
      const glm::ivec2 columns = hullColumns(ends, float(y), float(y + 1), box, 1);
      for (int x = box.min.x; x <= box.max.x; ++x) {
        const glm::vec3 direction = glm::normalize(rayThrough(view, cellSamplePosition(glm::uvec2(x, y), 1)));
        const float t = capsuleHit(view.eye, direction, a, b, r);
        if (t == kNoHit) continue;
        const glm::vec3 p = view.eye + t * direction;
        ASSERT_LT(glm::distance(p, glm::mix(a, b, alongSegment(p, a, b))), 1.01f * r) << "trial " << trial;
        ++hits;
        ASSERT_TRUE(x >= columns.x && x <= columns.y) << "trial " << trial << " cell " << x << "," << y
                                                      << " outside the hull's " << columns.x << ".." << columns.y;
      }
    }
  }
  EXPECT_GT(hits, 10000u * kTrials / 60);  // the segments do cross the view (10,000 hits in 60 trials)
}

TEST(NoodlesCapsule, BoxIsEmptyBehindTheCameraAndOffScreen) {
  const glm::uvec2 pixels{64, 36};
  const ScreenView view = testView({0.0f, -3.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, glm::vec2(pixels));
  EXPECT_TRUE(capsuleScreenBox(view, {0.0f, -5.0f, 0.0f}, {0.1f, -4.0f, 0.0f}, 0.05f).empty());  // behind
  EXPECT_TRUE(capsuleScreenBox(view, {0.0f, -2.9f, 0.0f}, {0.1f, -2.9f, 0.0f}, 0.05f).empty());  // nearer than near
  EXPECT_TRUE(capsuleScreenBox(view, {50.0f, 0.0f, 0.0f}, {51.0f, 0.0f, 0.0f}, 0.05f).empty());  // far right
  EXPECT_FALSE(capsuleScreenBox(view, {-0.1f, 0.0f, 0.0f}, {0.1f, 0.0f, 0.0f}, 0.05f).empty());
  // A capsule whose end sphere reaches the eye's plane takes the whole image.
  const PixelBox close = capsuleScreenBox(view, {0.0f, -2.8f, 0.0f}, {0.0f, 0.0f, 0.0f}, 0.3f);
  EXPECT_EQ(close.min, glm::vec2(0.0f));
  EXPECT_EQ(close.max, glm::vec2(pixels));
}

// A tile the test turns away holds no hit, for random capsules near, far, crossing the near plane
// and off-screen; and for a long, thin tube seen across the image most of its box is turned away.
TEST(NoodlesCapsule, TilesTurnedAwayHoldNoHit) {
  const glm::uvec2 pixels{64, 36};
  const ScreenView view = testView({0.0f, -3.0f, 0.5f}, {0.0f, 0.0f, 0.0f}, glm::vec2(pixels));
  std::mt19937 rng(61);
  std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f), radius(0.005f, 0.3f), length(0.02f, 3.0f);
  int turnedAway = 0, kept = 0;
  const int kTrials = test::trials(200);
  for (int trial = 0; trial < kTrials; ++trial) {
    const glm::vec3 a{coordinate(rng), coordinate(rng) - 1.0f, coordinate(rng)};
    const glm::vec3 b = a + length(rng) * glm::normalize(glm::vec3(coordinate(rng), coordinate(rng), coordinate(rng)));
    const float r = radius(rng);
    for (const uint32_t samples : {1u, 2u})
      for (const uint32_t side : {4u, 8u})
        for (uint32_t ty = 0; ty < pixels.y * samples; ty += side)
          for (uint32_t tx = 0; tx < pixels.x * samples; tx += side) {
            if (tileMayHit(view, a, b, r, {tx, ty}, side, samples)) {
              ++kept;
              continue;
            }
            ++turnedAway;
            for (uint32_t y = ty; y < std::min(ty + side, pixels.y * samples); ++y)
              for (uint32_t x = tx; x < std::min(tx + side, pixels.x * samples); ++x) {
                const glm::vec3 direction = glm::normalize(rayThrough(view, cellSamplePosition({x, y}, samples)));
                ASSERT_EQ(capsuleHit(view.eye, direction, a, b, r), kNoHit)
                    << "trial " << trial << " tile " << tx << "," << ty << " side " << side << " cell " << x << "," << y;
              }
          }
  }
  EXPECT_GT(turnedAway, kept);  // the random tubes are thin: most tiles are turned away

  // A thin diagonal tube across the view: its box is the whole image, its tiles mostly empty.
  const glm::vec3 a{-1.5f, 0.0f, -0.8f}, b{1.5f, 0.0f, 1.8f};
  const CellBox box = cellsOf(capsuleScreenBox(view, a, b, 0.01f), 2, pixels);
  uint32_t tiles = 0, mayHit = 0;
  for (int y = box.min.y; y <= box.max.y; y += 8)
    for (int x = box.min.x; x <= box.max.x; x += 8) {
      ++tiles;
      if (tileMayHit(view, a, b, 0.01f, glm::uvec2(x, y), 8, 2)) ++mayHit;
    }
  EXPECT_GT(tiles, 100u);
  EXPECT_LT(mayHit * 3, tiles) << mayHit << " of " << tiles << " tiles kept";
}

// No hit of random rays at random capsules lies nearer than the bound, and the bound is reached: a
// ray straight at the axis' nearest point hits at it.
TEST(NoodlesCapsule, NoHitIsNearerThanTheNearestPossible) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f), radius(0.01f, 0.5f);
  const glm::vec3 eye{0.0f, -4.0f, 0.3f};
  int hits = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const glm::vec3 a{coordinate(rng), coordinate(rng), coordinate(rng)}, b{coordinate(rng), coordinate(rng), coordinate(rng)};
    const float r = radius(rng);
    const glm::vec3 target = glm::mix(a, b, 0.5f) + 0.3f * glm::vec3(coordinate(rng), coordinate(rng), coordinate(rng));
    const float t = capsuleHit(eye, glm::normalize(target - eye), a, b, r);
    if (t == kNoHit) continue;
    ++hits;
    EXPECT_GE(t, nearestPossibleHit(eye, a, b, r) * (1.0f - 1e-5f)) << "trial " << trial;
  }
  EXPECT_GT(hits, 200);
  const glm::vec3 a{-1.0f, 0.0f, 0.0f}, b{1.0f, 0.0f, 0.0f};
  EXPECT_NEAR(capsuleHit(eye, glm::normalize(glm::vec3(0.0f) - eye), a, b, 0.2f), nearestPossibleHit(eye, a, b, 0.2f),
              1e-5f);
}

}  // namespace
}  // namespace vitrine::noodles
