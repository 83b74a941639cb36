// An output's warp (maths/output_warp.h, mirrored by the present pass): turns, mirrors, regions, corner
// pins and soft edges map each output position to the frame position it must show.
#include <gtest/gtest.h>

#include "maths/output_warp.h"

namespace vitrine::maths {
namespace {

void expectNear(glm::vec2 a, glm::vec2 b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
}

glm::vec2 shown(const OutputWarp& warp, glm::vec2 output) {
  const WarpMatrices m = warpMatrices(warp);
  const auto picture = unpin(m, output);
  EXPECT_TRUE(picture.has_value()) << output.x << " " << output.y;
  return picture ? toSource(m, *picture) : glm::vec2(-1.0f);
}

TEST(OutputWarp, TheIdentityShowsEachPositionItself) {
  const OutputWarp warp;
  EXPECT_TRUE(warp.isIdentity());
  EXPECT_EQ(checkWarp(warp), "");
  for (glm::vec2 p : {glm::vec2(0.0f), glm::vec2(0.25f, 0.75f), glm::vec2(1.0f)}) expectNear(shown(warp, p), p);
}

TEST(OutputWarp, QuarterTurnsAreClockwiseAndTheMirrorComesAfter) {
  OutputWarp warp;
  warp.quarterTurns = 1;  // the frame's top-left corner shows at the output's top-right
  expectNear(shown(warp, {1.0f, 0.0f}), {0.0f, 0.0f});
  expectNear(shown(warp, {0.0f, 0.0f}), {0.0f, 1.0f});
  warp.quarterTurns = 2;
  expectNear(shown(warp, {0.2f, 0.1f}), {0.8f, 0.9f});
  warp.quarterTurns = 3;  // top-left shows at the bottom-left
  expectNear(shown(warp, {0.0f, 1.0f}), {0.0f, 0.0f});
  warp.quarterTurns = 0;
  warp.mirror = true;
  expectNear(shown(warp, {0.1f, 0.3f}), {0.9f, 0.3f});
  warp.quarterTurns = 1;  // turned, then mirrored: the top-left comes back to the top-left
  expectNear(shown(warp, {0.0f, 0.0f}), {0.0f, 0.0f});
}

TEST(OutputWarp, ARegionShowsItsPartOfTheFrame) {
  OutputWarp right;
  right.region = {0.5f, 0.0f, 1.0f, 1.0f};  // the right-hand projector of a pair
  expectNear(shown(right, {0.0f, 0.5f}), {0.5f, 0.5f});
  expectNear(shown(right, {1.0f, 1.0f}), {1.0f, 1.0f});
}

TEST(OutputWarp, PinnedCornersShowTheFramesCornersAndNothingOutside) {
  OutputWarp warp;
  warp.corners = {glm::vec2(0.1f, 0.05f), glm::vec2(0.95f, 0.0f), glm::vec2(0.8f, 0.9f), glm::vec2(0.2f, 1.0f)};
  ASSERT_EQ(checkWarp(warp), "");
  const glm::vec2 frameCorners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) expectNear(shown(warp, warp.corners[size_t(i)]), frameCorners[i], 1e-4f);
  // The pin is projective: the picture's centre is where its diagonals cross, not the corners' mean.
  const glm::mat3 pin = pinMatrix(warp.corners);
  const glm::vec3 centre = pin * glm::vec3(0.5f, 0.5f, 1.0f);
  expectNear(shown(warp, glm::vec2(centre) / centre.z), {0.5f, 0.5f}, 1e-4f);
  EXPECT_FALSE(unpin(warpMatrices(warp), {0.02f, 0.5f}));  // left of the pinned picture: black
  EXPECT_FALSE(unpin(warpMatrices(warp), {0.5f, 0.99f}));
}

TEST(OutputWarp, RefusesWhatCannotBeShown) {
  OutputWarp crossed;
  std::swap(crossed.corners[1], crossed.corners[2]);
  EXPECT_NE(checkWarp(crossed).find("convex"), std::string::npos);
  OutputWarp flat;
  flat.corners[1] = {0.5f, 0.5f};
  flat.corners[0] = {0.0f, 0.0f};
  flat.corners[2] = {1.0f, 1.0f};
  EXPECT_NE(checkWarp(flat), "");
  OutputWarp region;
  region.region = {0.6f, 0.0f, 0.4f, 1.0f};
  EXPECT_NE(checkWarp(region).find("region"), std::string::npos);
  OutputWarp wide;
  wide.blend.left = 0.6f;
  EXPECT_NE(checkWarp(wide).find("0.5"), std::string::npos);
  OutputWarp turned;
  turned.quarterTurns = 4;
  EXPECT_NE(checkWarp(turned), "");
}

TEST(OutputWarp, OverlappingEdgesSumToEvenLight) {
  EdgeBlend blend;
  blend.right = 0.2f;
  blend.gamma = 1.0f;  // in linear light two ramps across the overlap add up to one
  for (float t : {0.0f, 0.1f, 0.37f, 0.5f, 0.81f, 1.0f}) {
    const float fromLeft = edgeRamp(t * 0.2f, 0.2f, blend.curve, blend.gamma);
    const float fromRight = edgeRamp((1.0f - t) * 0.2f, 0.2f, blend.curve, blend.gamma);
    EXPECT_NEAR(fromLeft + fromRight, 1.0f, 1e-5f) << t;
  }
  EXPECT_EQ(edgeWeight(blend, {0.5f, 0.5f}), 1.0f);  // inside the widths: untouched
  EXPECT_EQ(edgeWeight(blend, {1.0f, 0.5f}), 0.0f);  // at the blended edge: dark
  blend.gamma = 2.2f;  // a projector's gamma lifts the ramp so that its light, not its value, is even
  EXPECT_GT(edgeWeight(blend, {0.9f, 0.5f}), 0.5f);
}

}  // namespace
}  // namespace vitrine::maths
