#include "maths/color.h"
#include "maths/hash.h"
#include "scenes/kifs/kifs_math.h"
#include "scenes/quality.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vitrine {
namespace {

TEST(Aces, KnownValues) {
  EXPECT_FLOAT_EQ(maths::acesNarkowicz(0.0f), 0.0f);
  EXPECT_NEAR(maths::acesNarkowicz(1.0f), 2.34f / 4.01f, 1e-6f);
  EXPECT_NEAR(maths::acesNarkowicz(0.18f), (0.18f * (2.38f * 0.18f - 0.04f)) / (0.18f * (2.35f * 0.18f + 1.52f) + 0.14f),
              1e-7f);
  EXPECT_NEAR(maths::acesNarkowicz(1e6f), 2.38f / 2.35f, 1e-4f);  // the shoulder's asymptote
}

TEST(Aces, ToeCrushesToBlackInsteadOfGoingNegative) {
  for (float x = 0.0f; x < 0.0168f; x += 0.0005f) EXPECT_GE(maths::acesNarkowicz(x), 0.0f) << x;
}

TEST(Aces, MonotoneNonDecreasing) {
  float previous = maths::acesNarkowicz(0.0f);
  for (float x = 0.0f; x < 64.0f; x += 0.001f) {
    const float y = maths::acesNarkowicz(x);
    ASSERT_GE(y, previous - 1e-6f) << "at x = " << x;  // float rounding only
    previous = y;
  }
}

TEST(Hash, RangeIsHalfOpenUnitInterval) {
  double sum = 0.0;
  float lo = 1.0f, hi = 0.0f;
  constexpr int n = 200000;
  for (uint32_t i = 0; i < n; ++i) {
    const float h = maths::hash01({i % 641u, i / 641u, 17u});
    ASSERT_GE(h, 0.0f);
    ASSERT_LT(h, 1.0f);
    lo = std::min(lo, h), hi = std::max(hi, h);
    sum += h;
  }
  EXPECT_NEAR(sum / n, 0.5, 0.005);  // uniform
  EXPECT_LT(lo, 1e-3f);
  EXPECT_GT(hi, 1.0f - 1e-3f);
}

TEST(Hash, DifferentInputsDecorrelate) {
  EXPECT_NE(maths::hash01({1, 2, 3}), maths::hash01({1, 2, 4}));
  EXPECT_NE(maths::hash01({1, 2, 3}), maths::hash01({2, 1, 3}));
  EXPECT_EQ(maths::hash01({9, 9, 9}), maths::hash01({9, 9, 9}));
}

TEST(SmoothMin, StaysWithinAQuarterBandBelowMin) {
  for (float k : {0.1f, 0.3f})
    for (float a = -1.0f; a <= 1.0f; a += 0.05f)
      for (float b = -1.0f; b <= 1.0f; b += 0.05f) {
        const float s = kifs::smin(a, b, k);
        EXPECT_LE(s, std::min(a, b) + 1e-6f);
        EXPECT_GE(s, std::min(a, b) - k / 4.0f - 1e-6f);
      }
}

TEST(SmoothMin, EqualsMinOutsideTheBandAndDipsMostAtTheCrossover) {
  EXPECT_FLOAT_EQ(kifs::smin(0.0f, 1.0f, 0.3f), 0.0f);
  EXPECT_FLOAT_EQ(kifs::smin(1.0f, 0.0f, 0.3f), 0.0f);
  EXPECT_NEAR(kifs::smin(0.5f, 0.5f, 0.3f), 0.5f - 0.3f / 4.0f, 1e-6f);
}

TEST(SmoothMin, IsContinuous) {
  const float k = 0.3f, h = 1e-4f;
  for (float a = -0.5f; a <= 0.5f; a += 0.01f)
    EXPECT_LT(std::fabs(kifs::smin(a + h, 0.1f, k) - kifs::smin(a, 0.1f, k)), 2.0f * h);
}

TEST(Field, SphereStagesAreExactDistances) {
  EXPECT_NEAR(kifs::field({0, 0, 1}, 1).distance, 0.5f, 1e-6f);
  EXPECT_NEAR(kifs::field({0, -2, 0}, 2).distance, 1.5f, 1e-6f);
  EXPECT_EQ(kifs::tumble({0.3f, 0.2f, 0.1f}, 2, {0.7f, 0.3f}), glm::vec3(0.3f, 0.2f, 0.1f));  // sphere sits still
}

TEST(Field, TumbleIsARotation) {
  const glm::vec3 p{0.3f, -0.7f, 1.1f};
  const glm::vec3 q = kifs::tumble(p, 9, {0.9f, -0.4f});
  EXPECT_NEAR(glm::length(q), glm::length(p), 1e-6f);
  EXPECT_GT(glm::length(q - p), 0.1f);
  // Linear: tumbling the ray once equals tumbling every sample on it.
  const glm::vec3 o{0.1f, 0.2f, -4.5f}, d{0.0f, 0.6f, 0.8f};
  const glm::vec3 sample = kifs::tumble(o + 2.5f * d, 9, {0.9f, -0.4f});
  const glm::vec3 fromRay = kifs::tumble(o, 9, {0.9f, -0.4f}) + 2.5f * kifs::tumble(d, 9, {0.9f, -0.4f});
  EXPECT_NEAR(glm::length(sample - fromRay), 0.0f, 1e-5f);
}

TEST(Field, HardUnionIsTheNearestCylinder) {
  EXPECT_NEAR(kifs::field({0, 0, 0}, 3).distance, -kifs::kCylinders.z, 1e-6f);
  EXPECT_NEAR(kifs::field({1, 1, 0}, 3).distance, 1.0f - kifs::kCylinders.x, 1e-6f);
  EXPECT_LT(kifs::field({1, 1, 0}, 4).distance, kifs::field({1, 1, 0}, 3).distance + 1e-6f);
}

TEST(Field, FoldedEstimateOnKnownPoints) {
  // Inside the core sphere the estimate is negative; far away it grows with distance as a
  // distance estimate scaled by the write-up's 0.3 should.
  EXPECT_LT(kifs::field({0, 0, 0}, 9).distance, 0.0f);
  const float far = kifs::field({0, 0, 20}, 9).distance;
  const float farther = kifs::field({0, 0, 40}, 9).distance;
  EXPECT_GT(far, 0.0f);
  EXPECT_GT(farther, far);
  // The fold mirrors space: the estimate ignores the signs of the (warped) coordinates before the
  // fold, so points whose warp is zero (sin of 0) and mirrored agree.
  EXPECT_NEAR(kifs::field({0, 0, 0}, 6).distance, kifs::field({0, 0, 0}, 9).distance, 1e-6f);
  // Stages 6..9 differ only in shading, not in the field.
  EXPECT_EQ(kifs::field({0.3f, -0.2f, 0.1f}, 6).distance,
            kifs::field({0.3f, -0.2f, 0.1f}, 9).distance);
}

TEST(Field, MarchAlwaysAdvances) {
  for (int step = 1; step <= kifs::kStepCount; ++step) {
    EXPECT_GE(kifs::marchStep(0.0f, step), 0.015f);
    EXPECT_GE(kifs::marchStep(-0.3f, step), 0.015f);  // abs(d): never backwards inside a solid
  }
  EXPECT_NEAR(kifs::marchStep(1.0f, 2), 0.465f, 1e-6f);
}

TEST(Vignette, QuadraticFalloff) {
  EXPECT_FLOAT_EQ(kifs::vignette({0, 0}), 1.0f);
  EXPECT_NEAR(kifs::vignette({0.5f, 0.5f}), 1.0f - 0.55f * 0.5f, 1e-6f);
}

// The finished picture's display value along a grid of the shader's rays (stage 9, no jitter), at a
// march budget: what a tier's budget changes is measured on the rays themselves.
std::vector<glm::vec3> displayRays(int maxSteps) {
  const glm::vec2 angles = kifs::tumbleAngles(3.0, {});  // the golden frames' moment
  std::vector<glm::vec3> out;
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 64; ++x) {
      const glm::vec2 uv{(x + 0.5f - 32.0f) / 36.0f, -(y + 0.5f - 18.0f) / 36.0f};
      const glm::vec3 ro = kifs::tumble({0.0f, 0.0f, -4.5f}, 9, angles);
      const glm::vec3 rd = kifs::tumble(glm::normalize(glm::vec3(uv, 1.0f)), 9, angles);
      const glm::vec3 glow = kifs::marchGlow(ro, rd, 0.0f, 9, maxSteps) * kifs::vignette(uv) * 0.9f;
      out.push_back(kifs::kNavy + maths::acesNarkowicz(glow));
    }
  return out;
}

// Share of rays whose display value moves by more than the golden metric's 0.1 per channel.
double shareMoved(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  size_t moved = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    const glm::vec3 d = glm::abs(a[i] - b[i]);
    moved += std::max(d.x, std::max(d.y, d.z)) > 0.1f;
  }
  return double(moved) / double(a.size());
}

TEST(KifsTiers, EveryTierMarchesThePictureOfTheFullBudget) {
  const auto full = displayRays(kifs::kTierMarch[int(Tier::High)].marchSteps);
  double fullMean = 0.0;
  for (const auto& c : full) fullMean += c.r + c.g + c.b;
  for (const Tier tier : {Tier::Medium, Tier::Low}) {
    const auto rays = displayRays(kifs::kTierMarch[int(tier)].marchSteps);
    double mean = 0.0;
    for (const auto& c : rays) mean += c.r + c.g + c.b;
    EXPECT_LT(shareMoved(full, rays), 0.005) << "tier " << int(tier) << " changes the picture";
    EXPECT_NEAR(mean / fullMean, 1.0, 0.01) << "tier " << int(tier) << " dims the frame";
  }
  // The old low tier's 40 steps cut the core's rays short: stripes across it, a dimmer frame.
  EXPECT_GT(shareMoved(full, displayRays(40)), 0.01);
}

// The finished frame's luminance at orientation `angles`, 32x18 cells of 4x4 rays each (stage 9, no
// jitter): averaging the rays keeps the warp's fine filaments from aliasing into noise at this size.
std::vector<float> frameLuminance(glm::vec2 angles, int wide, int high) {
  constexpr int kRaysPerSide = 4;
  std::vector<float> out;
  for (int y = 0; y < high; ++y)
    for (int x = 0; x < wide; ++x) {
      float sum = 0.0f;
      for (int j = 0; j < kRaysPerSide; ++j)
        for (int i = 0; i < kRaysPerSide; ++i) {
          const glm::vec2 pixel{x + (i + 0.5f) / kRaysPerSide, y + (j + 0.5f) / kRaysPerSide};
          const glm::vec2 uv{(pixel.x - 0.5f * wide) / high, -(pixel.y - 0.5f * high) / high};
          const glm::vec3 ro = kifs::tumble({0.0f, 0.0f, -4.5f}, 9, angles);
          const glm::vec3 rd = kifs::tumble(glm::normalize(glm::vec3(uv, 1.0f)), 9, angles);
          const glm::vec3 glow = kifs::marchGlow(ro, rd, 0.0f, 9, kifs::kTierMarch[int(Tier::High)].marchSteps);
          const glm::vec3 display = kifs::kNavy + maths::acesNarkowicz(glow * kifs::vignette(uv) * 0.9f);
          sum += glm::dot(display, glm::vec3(0.2126f, 0.7152f, 0.0722f));
        }
      out.push_back(sum / (kRaysPerSide * kRaysPerSide));
    }
  return out;
}

// How far the frame at `angles` is from its mirror image about the frame's vertical axis (x) and its
// horizontal axis (y): the mean absolute difference in luminance over the mean luminance, 0 when
// mirrored. Horizontal and vertical stripes through the middle, a starburst, mirror about both.
glm::vec2 mirrorDifference(glm::vec2 angles) {
  constexpr int kWide = 32, kHigh = 18;
  const std::vector<float> l = frameLuminance(angles, kWide, kHigh);
  auto at = [&](int x, int y) { return l[size_t(y * kWide + x)]; };
  double total = 0.0, acrossVertical = 0.0, acrossHorizontal = 0.0;
  for (int y = 0; y < kHigh; ++y)
    for (int x = 0; x < kWide; ++x) {
      total += at(x, y);
      acrossVertical += std::fabs(at(x, y) - at(kWide - 1 - x, y));
      acrossHorizontal += std::fabs(at(x, y) - at(x, kHigh - 1 - y));
    }
  return {float(acrossVertical / total), float(acrossHorizontal / total)};
}

// The turn's first seconds show the fractal askew. Unturned (the start at angles 0), the frame is a
// starburst of horizontal and vertical stripes: 0.078 and 0.081 from its mirror images, and 1 s into
// that turn still 0.13 about the horizontal axis; from kTumbleStart, 0.24 or more at 0, 1 and 3 s.
TEST(KifsTurn, TheFirstSecondsAreNotMirroredAboutTheFrameAxes) {
  const glm::vec2 unturned = mirrorDifference({0.0f, 0.0f});
  EXPECT_LT(std::max(unturned.x, unturned.y), 0.1f) << "the measure no longer sees the axis-aligned starburst";
  for (const double seconds : {0.0, 1.0, 3.0}) {
    const glm::vec2 turned = mirrorDifference(kifs::tumbleAngles(seconds, {}));
    EXPECT_GT(std::min(turned.x, turned.y), 0.2f) << "at " << seconds << " s: " << turned.x << ", " << turned.y;
  }
}

TEST(KifsTurn, TurnsContinuouslyFromItsStart) {
  EXPECT_EQ(kifs::tumbleAngles(0.0, {}), kifs::kTumbleStart);  // and reduced motion holds it
  const glm::vec2 drag{0.5f, -0.25f};
  EXPECT_NEAR(glm::length(kifs::tumbleAngles(0.0, drag) - (kifs::kTumbleStart + drag * kifs::kDragToAngle)), 0.0f,
              1e-6f);
  for (double t = 0.0; t < 60.0; t += 0.25) {  // no jump anywhere: a frame turns by the rate's 1/60
    const glm::vec2 step = kifs::tumbleAngles(t + 1.0 / 60.0, {}) - kifs::tumbleAngles(t, {});
    EXPECT_NEAR(glm::length(step), glm::length(kifs::kTumbleRate) / 60.0f, 1e-4f) << "at " << t << " s";
  }
}

TEST(KifsTiers, LowerTiersCostLess) {
  for (int t = int(Tier::High); t < int(Tier::Low); ++t) {
    const auto& a = kifs::kTierMarch[t];
    const auto& b = kifs::kTierMarch[t + 1];
    EXPECT_LT(b.marchSteps * b.renderScale * b.renderScale, a.marchSteps * a.renderScale * a.renderScale);
  }
}

TEST(AutoTier, StepsDownWhenSlowAndBackUpWhenFast) {
  AutoTier tier;
  for (int i = 0; i < 8; ++i) tier.observe(20.0, 8.0);
  EXPECT_EQ(tier.current(), Tier::Medium);
  for (int i = 0; i < 8; ++i) tier.observe(20.0, 8.0);
  EXPECT_EQ(tier.current(), Tier::Low);
  for (int i = 0; i < 60; ++i) tier.observe(1.0, 8.0);
  EXPECT_EQ(tier.current(), Tier::Medium);
  for (int i = 0; i < 30; ++i) tier.observe(8.0, 8.0);  // on target: holds
  EXPECT_EQ(tier.current(), Tier::Medium);
}

// A software device starts at the low tier and climbs while its frames leave room.
TEST(AutoTier, AStartAtTheLowTierStepsUpWhenFast) {
  AutoTier tier(Tier::Low);
  EXPECT_EQ(tier.current(), Tier::Low);
  for (int i = 0; i < 59; ++i) EXPECT_EQ(tier.observe(5.0, 16.0), Tier::Low);
  EXPECT_EQ(tier.observe(5.0, 16.0), Tier::Medium);
  for (int i = 0; i < 100; ++i) tier.observe(12.0, 16.0);  // within the target: stays
  EXPECT_EQ(tier.current(), Tier::Medium);
  EXPECT_EQ(AutoTier(Tier::Auto).current(), Tier::High);
}

TEST(AutoTier, FramesFarOverTheTargetStepDownAtOnceButOneHitchDoesNot) {
  AutoTier tier;
  tier.observe(100.0, 16.0);  // one hitch, then back on target
  tier.observe(16.0, 16.0);
  EXPECT_EQ(tier.current(), Tier::High);
  tier.observe(100.0, 16.0);  // two in a row, 6x over: one tier
  tier.observe(100.0, 16.0);
  EXPECT_EQ(tier.current(), Tier::Medium);

  AutoTier seconds;  // noodles' high tier on lavapipe: ~3 s a frame against 16 ms
  seconds.observe(2900.0, 16.0);
  EXPECT_EQ(seconds.current(), Tier::High);
  seconds.observe(2900.0, 16.0);
  EXPECT_EQ(seconds.current(), Tier::Low) << "straight to the lowest tier, after two frames, not sixteen";
}

}  // namespace
}  // namespace vitrine
