#include "host/present/screen_area.h"

#include <gtest/gtest.h>

#include <vector>

namespace vitrine::host {
namespace {

// Two monitors side by side: a 1920x1080 primary and a 2560x1440 to its right.
const std::vector<ScreenArea> kPair{{0, 0, 1920, 1080}, {1920, 0, 2560, 1440}};

TEST(ScreenArea, AWindowBelongsToTheMonitorHoldingMostOfIt) {
  EXPECT_EQ(mostShared({100, 100, 1280, 720}, kPair), 0u);
  EXPECT_EQ(mostShared({2000, 100, 1280, 720}, kPair), 1u);
  EXPECT_EQ(mostShared({1800, 100, 1280, 720}, kPair), 1u);  // 120 columns on the left, 1160 on the right
  EXPECT_EQ(mostShared({1000, 100, 1280, 720}, kPair), 0u);  // 920 on the left, 360 on the right
}

TEST(ScreenArea, AWindowOffEveryMonitorBelongsToNone) {
  EXPECT_EQ(mostShared({-2000, 0, 640, 360}, kPair), std::nullopt);
  EXPECT_EQ(mostShared({0, 1500, 640, 360}, kPair), std::nullopt);
  EXPECT_EQ(mostShared({0, 0, 640, 360}, {}), std::nullopt);
}

TEST(ScreenArea, EdgesThatOnlyTouchShareNothing) {
  EXPECT_EQ(sharedPixels({0, 0, 1920, 1080}, {1920, 0, 100, 100}), 0);
  EXPECT_EQ(sharedPixels({0, 0, 10, 10}, {5, 5, 10, 10}), 25);
  EXPECT_EQ(mostShared({1920 - 640, 0, 1280, 360}, kPair), 0u);  // equal halves: the first
}

}  // namespace
}  // namespace vitrine::host
