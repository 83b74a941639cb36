// The flash guard's arithmetic (host/flash_guard_math.h), which shaders/host/flash_guard.glsl and
// flash_decide.comp mirror: what a transition is, how large a flash must be, and the window that lets
// no more than three flashes a second through.
#include "host/flash_guard_math.h"

#include <gtest/gtest.h>

namespace vitrine::host::flash {
namespace {

const glm::vec3 kBlack{0.0f}, kWhite{1.0f}, kRed{1.0f, 0.0f, 0.0f};

TEST(FlashGuard, GeneralTransitionNeedsATenthOfTheRangeWithTheDarkerBelowFourFifths) {
  EXPECT_EQ(generalTransition(kBlack, kWhite), 1);
  EXPECT_EQ(generalTransition(kWhite, kBlack), -1);
  EXPECT_EQ(generalTransition(glm::vec3(0.30f), glm::vec3(0.39f)), 0);   // under a tenth
  EXPECT_EQ(generalTransition(glm::vec3(0.30f), glm::vec3(0.41f)), 1);
  EXPECT_EQ(generalTransition(glm::vec3(0.82f), glm::vec3(1.0f)), 0);    // both bright: not a flash
  EXPECT_EQ(generalTransition(glm::vec3(0.75f), glm::vec3(1.0f)), 1);    // the darker is below 0.8
  EXPECT_EQ(generalTransition(glm::vec3(4.0f), glm::vec3(1.0f)), 0);     // HDR over white shows as white
}

TEST(FlashGuard, LuminanceWeighsThePrimariesAsSrgbDoes) {
  EXPECT_NEAR(luminance(kWhite), 1.0f, 1e-6f);
  EXPECT_NEAR(luminance(glm::vec3(0.0f, 1.0f, 0.0f)), 0.7152f, 1e-6f);
  // Pure blue changes luminance by 0.07 only: a blue flash on black is no general transition.
  EXPECT_EQ(generalTransition(kBlack, glm::vec3(0.0f, 0.0f, 1.0f)), 0);
}

TEST(FlashGuard, RedTransitionNeedsASaturatedRedAndAChangeOverTwenty) {
  EXPECT_TRUE(saturatedRed(kRed));
  EXPECT_TRUE(saturatedRed(glm::vec3(0.8f, 0.1f, 0.1f)));
  EXPECT_FALSE(saturatedRed(glm::vec3(0.7f, 0.2f, 0.2f)));
  EXPECT_FALSE(saturatedRed(kBlack));
  EXPECT_EQ(redTransition(kBlack, kRed), 1);
  EXPECT_EQ(redTransition(kRed, kBlack), -1);
  EXPECT_EQ(redTransition(kWhite, kBlack), 0);  // no red on either side
  // 320 x (R - G - B) must move by more than 20: 0.0625 of red.
  EXPECT_EQ(redTransition(glm::vec3(0.90f, 0.0f, 0.0f), glm::vec3(0.95f, 0.0f, 0.0f)), 0);
  EXPECT_EQ(redTransition(glm::vec3(0.80f, 0.0f, 0.0f), glm::vec3(0.90f, 0.0f, 0.0f)), 1);
}

TEST(FlashGuard, AreaIsAQuarterOfATenDegreeFieldScaledToTheOutput) {
  EXPECT_EQ(flashArea(1024, 768), 341u * 256u);
  EXPECT_EQ(flashArea(2048, 1536), 4u * 341u * 256u);
  EXPECT_NEAR(double(flashArea(1920, 1080)) / (1920.0 * 1080.0), 0.111, 0.001);
  EXPECT_EQ(frameTransitions(1000, 0, 1000), 1);
  EXPECT_EQ(frameTransitions(999, 999, 1000), 0);
  EXPECT_EQ(frameTransitions(1000, 1000, 1000), 2);
}

// A square wave of `hz` sampled at `fps` for `seconds`: how many transitions the window admits in
// each second-long stretch, at most.
int mostInAnySecond(float hz, float fps, float seconds) {
  Ages ages = neverFlashed();
  std::vector<float> admittedAt;
  bool shown = false;  // what the held output shows: the guard holds it when a change is refused
  for (int k = 1; k < int(seconds * fps); ++k) {
    const float t = float(k) / fps;
    const bool lit = t * hz - std::floor(t * hz) < 0.5f;
    const int wanted = lit != shown ? 1 : 0;
    if (admit(ages, 1.0f / fps, wanted) && wanted) {
      shown = lit;
      admittedAt.push_back(t);
    }
  }
  int most = 0;
  for (size_t i = 0; i < admittedAt.size(); ++i) {
    int n = 0;
    for (size_t j = i; j < admittedAt.size() && admittedAt[j] <= admittedAt[i] + 1.0f + 1e-4f; ++j) ++n;
    most = std::max(most, n);
  }
  return most;
}

TEST(FlashGuard, WindowAdmitsNoMoreThanThreeFlashesInAnySecond) {
  EXPECT_EQ(mostInAnySecond(10.0f, 30.0f, 5.0f), kMaxTransitions);  // three flashes, then held
  EXPECT_EQ(mostInAnySecond(10.0f, 60.0f, 5.0f), kMaxTransitions);
  EXPECT_EQ(mostInAnySecond(25.0f, 60.0f, 5.0f), kMaxTransitions);
  EXPECT_EQ(mostInAnySecond(2.0f, 60.0f, 5.0f), 4 + 1);  // two flashes a second pass untouched (5: both ends)
}

TEST(FlashGuard, FramesWithinTheThresholdsAreAlwaysAdmitted) {
  Ages ages = neverFlashed();
  for (int k = 0; k < 600; ++k) EXPECT_TRUE(admit(ages, 1.0f / 60.0f, k % 20 == 0 ? 1 : 0));  // 3 a second
  EXPECT_EQ(transitionsInWindow(ages), 3);
}

TEST(FlashGuard, RefusedFramesTakeNoSlotAndTheWindowFreesUp) {
  Ages ages = neverFlashed();
  for (int n = 0; n < kMaxTransitions; ++n) EXPECT_TRUE(admit(ages, 0.01f, 1));
  EXPECT_FALSE(admit(ages, 0.01f, 1));
  EXPECT_FALSE(admit(ages, 0.5f, 2));
  EXPECT_EQ(transitionsInWindow(ages), kMaxTransitions);
  EXPECT_TRUE(admit(ages, 0.6f, 1));  // the first ones are over a second old now
}

}  // namespace
}  // namespace vitrine::host::flash
