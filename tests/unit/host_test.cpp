#include "gpu/check.h"
#include "image/image_compare.h"
#include "core/stats.h"
#include "support/images.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace vitrine {
namespace {

using test::flatImage;

TEST(Compare, IdenticalImagesPass) {
  const auto a = flatImage(16, 16, 0.3f);
  const auto r = compareImages(a, a);
  EXPECT_TRUE(r.passed);
  EXPECT_EQ(r.failing, 0u);
}

TEST(Compare, OneWrongPixelBeyondTheHardLimitFails) {
  const auto a = flatImage(64, 64, 0.3f);
  auto b = a;
  b.at(10, 10)[1] = 0.9f;
  EXPECT_FALSE(compareImages(a, b).passed);
}

TEST(Compare, SmallRoundingPasses) {
  const auto a = flatImage(64, 64, 0.3f);
  auto b = a;
  for (float& v : b.pixels) v += 0.004f;
  EXPECT_TRUE(compareImages(a, b).passed);
}

TEST(Compare, ColourShiftAcrossTheImageFails) {
  const auto a = flatImage(64, 64, 0.5f);
  auto b = a;
  for (size_t i = 0; i < b.pixels.size(); i += 4) b.pixels[i] *= 1.2f;  // red +20 %
  EXPECT_FALSE(compareImages(a, b).passed);
}

TEST(Compare, NonFiniteFails) {
  const auto a = flatImage(8, 8, 0.5f);
  auto b = a;
  b.pixels[5] = std::numeric_limits<float>::quiet_NaN();
  const auto r = compareImages(a, b);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.nonFinite, 1u);
}

TEST(Compare, SizeMismatchFails) { EXPECT_FALSE(compareImages(flatImage(8, 8, 0), flatImage(8, 9, 0)).passed); }

TEST(Stats, NearestRankPercentiles) {
  std::vector<double> v;
  for (int i = 1; i <= 100; ++i) v.push_back(i);
  EXPECT_EQ(percentile(v, 50), 50);
  EXPECT_EQ(percentile(v, 95), 95);
  EXPECT_EQ(percentile({}, 50), 0);
}

}  // namespace
}  // namespace vitrine
