// The golden metric's second, low-passed comparison (8 x 8 blocks, as cases.txt gives it), on a real golden frame of a chaotic kifs stage:
// sparkle-like flips of single pixels pass it, while one broken region - which the loosened pixel
// share (12 % for those stages) lets through - fails it.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "image/image_compare.h"
#include "image/image_io.h"

namespace vitrine {
namespace {

// The thresholds cases.txt gives kifs stages 5-9.
CompareThresholds chaoticStage(int block) {
  CompareThresholds t;
  t.failFraction = 0.12;
  t.hardLimit = 1.0f;
  t.block = block;
  return t;
}

const ImageRgba& golden() {
  static const ImageRgba image = readImage(std::filesystem::path(VITRINE_GOLDEN_DIR) / "kifs_step7.exr");
  return image;
}

TEST(GoldenLowPass, BoxFilterAveragesBlocksAndPartialEdgeBlocks) {
  ImageRgba image{5, 2, std::vector<float>(5 * 2 * 4, 0.0f)};
  for (uint32_t x = 0; x < 4; ++x) image.at(x, 0)[0] = 1.0f;  // the first block's top row
  image.at(4, 1)[1] = 0.5f;
  const ImageRgba small = boxFilter(image, 4);
  ASSERT_EQ(small.width, 2u);
  ASSERT_EQ(small.height, 1u);
  EXPECT_FLOAT_EQ(small.at(0, 0)[0], 0.5f);   // 4 of 8 pixels
  EXPECT_FLOAT_EQ(small.at(1, 0)[1], 0.25f);  // the partial block holds 2 pixels
}

// The summary a failing low-passed golden prints: it once read a local `blocks` inside that local's own
// initialiser instead of the member (std::bad_alloc at -O2, so the failure could not report itself).
TEST(GoldenLowPass, AFailingLowPassedSummaryNamesItsBlocks) {
  ImageRgba image{16, 16, std::vector<float>(16 * 16 * 4, 0.5f)};
  ImageRgba darker = image;
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 8; ++x) darker.at(x, y)[0] = 0.2f;  // one block of four, 0.3 darker in red
  CompareThresholds thresholds = chaoticStage(8);
  thresholds.hardLimit = 1.0f;
  thresholds.failFraction = 1.0;
  const CompareResult result = compareImages(image, darker, thresholds);
  ASSERT_FALSE(result.passed);
  ASSERT_EQ(result.blocks, 4u);
  ASSERT_EQ(result.failingBlocks, 1u);
  const std::string summary = result.summary();
  EXPECT_NE(summary.find("FAIL: 64 failing pixels"), std::string::npos) << summary;
  EXPECT_NE(summary.find(", 1 of 4 blocks failing low-passed (max difference 0.30000)"), std::string::npos) << summary;
}

TEST(GoldenLowPass, SparkleFlipsPassBothComparisons) {
  ImageRgba flipped = golden();
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  size_t flips = 0;
  for (uint32_t y = 0; y < flipped.height; ++y)
    for (uint32_t x = 0; x < flipped.width; ++x)
      if (unit(random) < 0.06f) {  // 6 % of pixels, as a CPU of another generation flips them
        ++flips;
        const float change = (unit(random) - 0.5f) * 0.5f;
        for (int c = 0; c < 3; ++c) flipped.at(x, y)[c] = std::max(0.0f, flipped.at(x, y)[c] + change);
      }
  ASSERT_GT(flips, 1000u);
  const CompareResult result = compareImages(golden(), flipped, chaoticStage(8));
  EXPECT_TRUE(result.passed) << result.summary();
}

TEST(GoldenLowPass, OneBrokenRegionFailsOnlyTheLowPassedComparison) {
  ImageRgba broken = golden();
  for (uint32_t y = 40; y < 72; ++y)  // a 32 x 32 patch at the centre, 35 % darker: 4.9 % of the pixels
    for (uint32_t x = 80; x < 112; ++x)
      for (int c = 0; c < 3; ++c) broken.at(x, y)[c] *= 0.65f;
  const CompareResult pixelsOnly = compareImages(golden(), broken, chaoticStage(0));
  EXPECT_TRUE(pixelsOnly.passed) << "the pixel share alone should miss it (the hole this closes): "
                                 << pixelsOnly.summary();
  const CompareResult both = compareImages(golden(), broken, chaoticStage(8));
  EXPECT_FALSE(both.passed) << both.summary();
  EXPECT_GE(both.failingBlocks, 12u);
}

TEST(GoldenLowPass, AnExposureChangeFails) {
  ImageRgba brighter = golden();
  for (size_t i = 0; i < brighter.pixels.size(); ++i)
    if (i % 4 != 3) brighter.pixels[i] *= 1.15f;
  EXPECT_FALSE(compareImages(golden(), brighter, chaoticStage(8)).passed);
}

}  // namespace
}  // namespace vitrine
