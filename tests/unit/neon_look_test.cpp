#include "scenes/neon/camera.h"
#include "scenes/neon/facade.h"
#include "scenes/neon/tube_light.h"
#include "scenes/neon/look.h"
#include "scenes/noodles/camera.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vitrine::neon {
namespace {

TEST(LinearBurn, WhiteLeavesTheBaseAlone) {
  for (glm::vec3 base : {glm::vec3(0.0f), glm::vec3(0.2f, 0.5f, 0.9f), glm::vec3(3.0f, 0.01f, 1.0f)})
    EXPECT_LT(glm::length(linearBurn(base, glm::vec3(1.0f)) - base), 1e-6f);  // + 1 - 1 rounds in float
}

TEST(LinearBurn, BlackTakesAWholeUnitOff) {
  EXPECT_EQ(linearBurn(glm::vec3(0.2f, 0.7f, 1.0f), glm::vec3(0.0f)), glm::vec3(0.0f));  // display range: black
  EXPECT_EQ(linearBurn(glm::vec3(2.5f, 1.25f, 0.5f), glm::vec3(0.0f)), glm::vec3(1.5f, 0.25f, 0.0f));  // HDR
}

TEST(LinearBurn, NeverBrightensAndIsSymmetric) {
  for (float a = 0.0f; a <= 1.0f; a += 0.125f)
    for (float b = 0.0f; b <= 1.0f; b += 0.125f) {
      const glm::vec3 burned = linearBurn(glm::vec3(a), glm::vec3(b));
      EXPECT_LE(burned.x, std::min(a, b));
      EXPECT_GE(burned.x, 0.0f);
      EXPECT_EQ(burned, linearBurn(glm::vec3(b), glm::vec3(a)));
    }
}

constexpr float kNear = 0.1f, kAperture = 8.0f, kMaxRadius = 12.0f;
float cocAt(float linearDepth, float focal) {
  return circleOfConfusion(kNear / linearDepth, kNear, focal, kAperture, kMaxRadius);
}

TEST(CircleOfConfusion, ZeroAtTheFocalDistance) {
  for (float focal : {0.5f, 3.0f, 30.0f, 250.0f}) EXPECT_NEAR(cocAt(focal, focal), 0.0f, 1e-4f) << focal;
}

TEST(CircleOfConfusion, GrowsMonotonicallyAwayFromFocus) {
  const float focal = 20.0f;
  float previous = cocAt(focal, focal);             // zero up to the rounding of near / focal
  for (float z = focal; z < 5000.0f; z *= 1.01f) {  // behind: positive, growing
    const float c = cocAt(z, focal);
    ASSERT_GE(c, previous) << z;
    previous = c;
  }
  EXPECT_GT(previous, 0.9f * kAperture);
  previous = cocAt(focal, focal);
  for (float z = focal; z > kNear; z /= 1.01f) {  // in front: negative, growing in size
    const float c = cocAt(z, focal);
    ASSERT_LE(c, previous) << z;
    previous = c;
  }
  EXPECT_LT(cocAt(focal * 0.9f, focal), 0.0f);
  EXPECT_GT(cocAt(focal * 1.1f, focal), 0.0f);
}

TEST(CircleOfConfusion, ClampedToTheMaximumRadius) {
  EXPECT_FLOAT_EQ(circleOfConfusion(1.0f, kNear, 20.0f, kAperture, kMaxRadius), -kMaxRadius);  // the near plane
  EXPECT_FLOAT_EQ(circleOfConfusion(0.0f, kNear, 20.0f, kAperture, kMaxRadius), kAperture);    // the sky
  EXPECT_FLOAT_EQ(circleOfConfusion(0.0f, kNear, 20.0f, 40.0f, kMaxRadius), kMaxRadius);       // a wide aperture
  for (float d = 0.0f; d <= 1.0f; d += 0.001f)
    EXPECT_LE(std::abs(circleOfConfusion(d, kNear, 20.0f, 40.0f, kMaxRadius)), kMaxRadius);
}

TEST(Vignette, OneInTheMiddleFallingToTheCorners) {
  EXPECT_FLOAT_EQ(vignette(0.0f, 0.6f), 1.0f);
  EXPECT_FLOAT_EQ(vignette(0.3f, 0.6f), 1.0f);
  EXPECT_FLOAT_EQ(vignette(1.0f, 0.6f), 0.4f);
  EXPECT_FLOAT_EQ(vignette(0.8f, 0.0f), 1.0f);
  float previous = 1.0f;
  for (float r = 0.0f; r <= 1.2f; r += 0.01f) {
    const float v = vignette(r, 0.6f);
    ASSERT_LE(v, previous + 1e-7f) << r;
    previous = v;
  }
  EXPECT_LT(vignette(0.87f, 0.6f), vignette(0.49f, 0.6f));  // a 16:9 frame's side edge darker than its top
}

TEST(Mirror, KeepsTheHorizonAndIsAnInvolution) {
  for (float horizon : {0.0f, 412.5f, 900.0f}) {
    EXPECT_FLOAT_EQ(mirrorY(horizon, horizon), horizon);
    for (float y : {0.5f, 300.0f, 1079.5f}) {
      EXPECT_FLOAT_EQ(mirrorY(mirrorY(y, horizon), horizon), y);
      EXPECT_FLOAT_EQ(mirrorY(y, horizon) - horizon, horizon - y);  // as far on the other side
    }
  }
  EXPECT_LT(mirrorY(700.0f, 600.0f), 600.0f);  // the ground looks up the facade above the line
}

TEST(Mirror, ProjectedRowOfAPointAheadIsTheMiddle) {
  const glm::mat4 projection = noodles::reverseZPerspective(0.8f, 16.0f / 9.0f, 0.1f);  // camera looks down -z, y up
  EXPECT_NEAR(projectedRow(projection, {0.0f, 0.0f, -10.0f}, 1080.0f), 540.0f, 1e-3f);
  EXPECT_LT(projectedRow(projection, {0.0f, 1.0f, -10.0f}, 1080.0f), 540.0f);  // above: nearer the top row
  EXPECT_NEAR(projectedRow(projection, {0.0f, -10.0f * std::tan(0.4f), -10.0f}, 1080.0f), 1080.0f, 1e-2f);
}

TEST(Spiral, TapsStayInsideTheUnitDisc) {
  for (uint32_t n : {24u, 32u})
    for (uint32_t i = 0; i < n; ++i) EXPECT_LE(glm::length(spiralTap(i, n)), 1.0f + 1e-6f) << i << " of " << n;
}

// The depth of field walks the spiral (each direction the last one turned by the golden angle) rather
// than taking a cos and a sin a tap: the same taps, to within float rounding, up to the most it takes.
TEST(Spiral, WalkingTheSpiralReachesTheSameTaps) {
  for (uint32_t n : {1u, 8u, 24u, 32u}) {
    glm::vec2 heading(1.0f, 0.0f);
    for (uint32_t i = 0; i < n; ++i, heading = nextHeading(heading))
      EXPECT_LT(glm::length(heading * spiralRadius(i, n) - spiralTap(i, n)), 2e-6f) << i << " of " << n;
  }
  EXPECT_NEAR(glm::length(kGoldenTurn), 1.0f, 1e-7f);
  EXPECT_NEAR(std::atan2(kGoldenTurn.y, kGoldenTurn.x), kGoldenAngle, 1e-6f);
}

TEST(Spiral, TapsCoverTheDiscEvenly) {
  constexpr uint32_t n = 32;
  int inner = 0, quadrants[4] = {};
  glm::vec2 mean(0.0f);
  float closest = std::numeric_limits<float>::max();
  for (uint32_t i = 0; i < n; ++i) {
    const glm::vec2 t = spiralTap(i, n);
    inner += glm::length(t) < std::sqrt(0.5f);  // the inner disc holds half the area
    ++quadrants[(t.x < 0.0f ? 1 : 0) + (t.y < 0.0f ? 2 : 0)];
    mean += t / float(n);
    for (uint32_t j = 0; j < i; ++j) closest = std::min(closest, glm::length(t - spiralTap(j, n)));
  }
  EXPECT_NEAR(inner, int(n / 2), 1);
  for (int q : quadrants) EXPECT_NEAR(q, int(n / 4), 2);
  EXPECT_LT(glm::length(mean), 0.05f);
  // No clumps: an even spread of 32 points leaves each about sqrt(pi / 32) = 0.31 apart.
  EXPECT_GT(closest, 0.15f);
}

TEST(Bloom, LevelsStopAroundSixteenRows) {
  EXPECT_EQ(bloomLevels(1080), 6);  // 1080 >> 6 = 16 rows
  EXPECT_EQ(bloomLevels(2160), 7);
  EXPECT_EQ(bloomLevels(20), 1);
  EXPECT_EQ(bloomLevels(1u << 20), 8);
}

TEST(Facade, BoxCountAndSizes) {
  const auto boxes = facadeBoxes();
  EXPECT_GE(boxes.size(), 30u);
  EXPECT_LE(boxes.size(), 80u);
  for (const Box& box : boxes) {
    EXPECT_GT(box.halfSize.x, 0.0f);
    EXPECT_GT(box.halfSize.y, 0.0f);
    EXPECT_GT(box.halfSize.z, 0.0f);
  }
}

TEST(Facade, StandsOnAGroundSlabReachingTowardsTheCamera) {
  const auto boxes = facadeBoxes();
  const auto ground = std::find_if(boxes.begin(), boxes.end(), [](const Box& b) {
    return std::abs(b.centre.y + b.halfSize.y) < 1e-6f && b.centre.x - b.halfSize.x < -kFacadeHalfWidth &&
           b.centre.x + b.halfSize.x > kFacadeHalfWidth && b.centre.z - b.halfSize.z < 0.0f &&
           b.centre.z + b.halfSize.z > 30.0f;
  });
  ASSERT_NE(ground, boxes.end());
  float top = 0.0f, frontMost = -1e9f;
  for (const Box& b : boxes) {
    if (&b == &*ground) continue;
    EXPECT_GE(b.centre.y - b.halfSize.y, -1e-6f);  // everything else stands on it
    top = std::max(top, b.centre.y + b.halfSize.y);
    if (b.centre.y + b.halfSize.y > 5.0f) frontMost = std::max(frontMost, b.centre.z + b.halfSize.z);
  }
  EXPECT_GE(top, kFacadeHeight);
  EXPECT_LT(frontMost, 1.0f);  // above the canopy, only ledges and the cornice stand out from z = 0
}

TEST(Facade, SuggestedCameraFramesTheFrontAndTheGround) {
  constexpr float aspect = 16.0f / 9.0f, height = 1080.0f;
  const glm::mat4 viewProjection = noodles::reverseZPerspective(kCameraFovY, aspect, 0.1f) *
                                   glm::lookAt(kCameraEye, kCameraTarget, {0.0f, 1.0f, 0.0f});
  const auto ndc = [&](glm::vec3 p) {
    const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
    EXPECT_GT(clip.w, 0.0f);
    return glm::vec2(clip) / clip.w;
  };
  for (glm::vec3 corner : {glm::vec3(-10.5f, 20.5f, 0.8f), glm::vec3(10.5f, 20.5f, 0.8f), glm::vec3(-10.0f, 0.0f, 0.0f),
                           glm::vec3(10.0f, 0.0f, 0.0f)}) {
    const glm::vec2 p = ndc(corner);
    EXPECT_LT(std::abs(p.x), 0.9f) << corner.x << ", " << corner.y;
    EXPECT_LT(std::abs(p.y), 0.95f) << corner.x << ", " << corner.y;
  }
  const float foot = projectedRow(viewProjection, {0.0f, 0.0f, 0.0f}, height);
  EXPECT_NEAR(foot / height, 0.79f, 0.02f);
  EXPECT_GT(projectedRow(viewProjection, {0.0f, 0.0f, 15.0f}, height), foot);    // ground nearer the camera: lower
  EXPECT_LT(projectedRow(viewProjection, {0.0f, 0.0f, 15.0f}, height), height);  // and still in the frame
}

TEST(FacadeUv, PicksTheDominantAxis) {
  const glm::vec3 p{4.0f, 5.0f, 15.0f};  // three different fractions across the UV box
  const glm::vec3 t = (p - kFacadeUvMin) / (kFacadeUvMax - kFacadeUvMin);
  const glm::vec2 side{t.z, 1.0f - t.y}, top{t.x, t.z}, front{t.x, 1.0f - t.y};
  const glm::vec2 range{0.0f, 1.0f};
  const auto near = [](glm::vec2 a, glm::vec2 b) { return glm::length(a - b) < 1e-6f; };
  for (float sign : {1.0f, -1.0f}) {
    EXPECT_TRUE(near(facadeUv(p, {sign, 0.0f, 0.0f}, range), side)) << sign;
    EXPECT_TRUE(near(facadeUv(p, {0.0f, sign, 0.0f}, range), top)) << sign;
    EXPECT_TRUE(near(facadeUv(p, {0.0f, 0.0f, sign}, range), front)) << sign;
  }
  EXPECT_TRUE(near(facadeUv(p, {0.3f, -0.2f, -0.9f}, range), front));  // tilted and not unit length
  EXPECT_TRUE(near(facadeUv(p, {-2.0f, 0.5f, 1.0f}, range), side));
}

TEST(FacadeUv, RangeMapsTheUvBoxEdges) {
  const glm::vec3 normal{0.0f, 0.0f, 1.0f};
  const glm::vec2 range{0.25f, 2.25f};
  EXPECT_NEAR(glm::length(facadeUv({-10.0f, 20.0f, 0.0f}, normal, range) - glm::vec2(0.25f)), 0.0f, 1e-6f);  // top left
  EXPECT_NEAR(glm::length(facadeUv({10.0f, 0.0f, 0.0f}, normal, range) - glm::vec2(2.25f)), 0.0f, 1e-6f);
}

float texelLuminance(const std::vector<uint8_t>& texels, uint32_t size, glm::vec2 uv) {
  const uint32_t col = std::min(uint32_t(uv.x * size), size - 1), row = std::min(uint32_t(uv.y * size), size - 1);
  const uint8_t* t = &texels[(size_t(row) * size + col) * 4];
  return 0.2126f * t[0] + 0.7152f * t[1] + 0.0722f * t[2];
}

TEST(FacadeLighting, SizeAndVariety) {
  constexpr uint32_t size = 128;
  const auto texels = facadeLightingTexture(size);
  ASSERT_EQ(texels.size(), size_t(size) * size * 4);
  uint8_t lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0};
  for (size_t i = 0; i < texels.size(); i += 4) {
    for (int c = 0; c < 3; ++c) lo[c] = std::min(lo[c], texels[i + c]), hi[c] = std::max(hi[c], texels[i + c]);
    ASSERT_EQ(texels[i + 3], 255);
  }
  for (int c = 0; c < 3; ++c) EXPECT_GT(hi[c] - lo[c], 40) << "channel " << c;
}

TEST(FacadeLighting, BrightUnderLedgesDarkInRecesses) {
  constexpr uint32_t size = 256;
  const auto texels = facadeLightingTexture(size);
  const glm::vec3 front{0.0f, 0.0f, 1.0f};
  const float bay = 0.5f * (kPillarX[1] + kPillarX[2]);
  const float ledge = 2.0f * kStorey + 0.7f;  // the second storey's ledge underside
  const float underLedge = texelLuminance(texels, size, facadeUv({bay, ledge - 0.3f, 0.0f}, front, {0.0f, 1.0f}));
  const float window =
      texelLuminance(texels, size, facadeUv({bay + 0.9f, ledge + 1.6f, kRecessZ}, front, {0.0f, 1.0f}));
  const float aboveLedge = texelLuminance(texels, size, facadeUv({bay, ledge + 0.3f, 0.0f}, front, {0.0f, 1.0f}));
  EXPECT_GT(underLedge, 2.0f * window);
  EXPECT_GT(underLedge, aboveLedge);
  // Warm at the street, cool near the top.
  const auto at = [&](float x, float y) {
    const glm::vec2 uv = facadeUv({x, y, 0.0f}, front, {0.0f, 1.0f});
    return &texels[(size_t(std::min(uint32_t(uv.y * size), size - 1)) * size + uint32_t(uv.x * size)) * 4];
  };
  EXPECT_GT(at(-7.0f, 1.0f)[0], at(-7.0f, 1.0f)[2]);
  EXPECT_LT(at(9.4f, 19.5f)[0], at(9.4f, 19.5f)[2]);
}

}  // namespace
}  // namespace vitrine::neon

namespace vitrine::neon {
namespace {

// Where a normalised cursor position projects to on screen again (0..1, origin top-left).
glm::vec2 onScreen(glm::vec3 world, float aspect) {
  const glm::vec4 clip = projectionMatrix(aspect) * viewMatrix() * glm::vec4(world, 1.0f);
  return glm::vec2(clip.x, clip.y) / clip.w * 0.5f + 0.5f;
}

// A drag over the ground (the lower fifth of the frame) used to release tubes under the floor, where
// the release plane runs below it; now it draws above the floor, under the cursor.
// The ground is its own wet surface, not the facade's texture printed on it: dark, warm near the
// storefront and falling off smoothly away from it (no window grid), and darker than the wall's foot.
TEST(Ground, DarkAndSmoothWithTheStorefrontsSpill) {
  const auto luminance = [](glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; };
  float previous = std::numeric_limits<float>::max();
  for (float z = 0.0f; z <= 40.0f; z += 0.25f) {  // out from the foot toward the camera
    const float l = luminance(groundLight({0.0f, 0.0f, z}));
    EXPECT_LE(l, previous) << z;
    previous = l;
  }
  for (float x = 0.0f; x <= 40.0f; x += 0.25f)  // along the foot, out to the slab's edge
    EXPECT_LE(luminance(groundLight({x + 0.25f, 0.0f, 1.0f})), luminance(groundLight({x, 0.0f, 1.0f}))) << x;
  const glm::vec3 foot = groundLight({0.0f, 0.0f, 0.0f});
  EXPECT_GT(foot.r, 2.0f * foot.b) << "the storefront's light is warm";
  EXPECT_LT(luminance(groundLight({0.0f, 0.0f, 20.0f})), 0.02f) << "away from the building the ground is dark";
  const auto texels = facadeLightingTexture(256);
  const glm::vec3 front{0.0f, 0.0f, 1.0f};
  const float wall = texelLuminance(texels, 256, facadeUv({0.0f, 0.3f, 0.0f}, front, {0.0f, 1.0f})) / 255.0f;
  EXPECT_LT(luminance(foot), std::pow(wall, 2.2f)) << "the ground is darker than the wall's foot (about linear)";
}

TEST(NeonRelease, EveryRowOfTheFrameReleasesAboveTheGround) {
  const float aspect = 16.0f / 9.0f;
  for (float y = 0.0f; y <= 1.0f; y += 0.02f)
    for (float x : {0.0f, 0.3f, 0.5f, 1.0f}) {
      const auto at = cursorOnReleasePlane({x, y}, aspect);
      ASSERT_TRUE(at) << x << " " << y;
      EXPECT_GE(at->y, kMinReleaseHeight - 1e-4f) << x << " " << y;
      EXPECT_LE(at->z, kReleasePlaneZ + 8.0f + 1e-4f);
      if (at->z < kReleasePlaneZ + 8.0f - 1e-3f) {  // on the cursor's ray: the tube is drawn under the cursor
        EXPECT_NEAR(glm::distance(onScreen(*at, aspect), glm::vec2(x, y)), 0.0f, 1e-4f) << x << " " << y;
      }
    }
  // Above the ground the release plane itself, as before.
  EXPECT_NEAR(cursorOnReleasePlane({0.5f, 0.4f}, aspect)->z, kReleasePlaneZ, 1e-4f);
  // The lower fifth, nearer the camera, at the lowest height.
  const auto low = *cursorOnReleasePlane({0.5f, 0.9f}, aspect);
  EXPECT_GT(low.z, kReleasePlaneZ);
  EXPECT_NEAR(low.y, kMinReleaseHeight, 1e-4f);
}

// The energy budget: one for a few tubes, then each tube dimmer, while the frame's total tube light
// still grows with the count, but slower than the count (so 4096 tubes are not 25x the light of 160).
TEST(NeonTubeLight, ExposureKeepsTheTotalLightGrowingSlowerThanTheCount) {
  EXPECT_EQ(tubeExposure(0), 1.0f);
  EXPECT_EQ(tubeExposure(uint32_t(kBudgetTubes)), 1.0f);
  float lastTotal = 0.0f, lastExposure = 1.0f;
  for (uint32_t n = 200; n <= 16384; n *= 2) {
    const float total = float(n) * tubeExposure(n);
    EXPECT_LT(tubeExposure(n), lastExposure);
    EXPECT_GT(total, lastTotal);
    lastTotal = total;
    lastExposure = tubeExposure(n);
  }
  EXPECT_LT(4096.0f * tubeExposure(4096), 4.0f * kBudgetTubes) << "4096 tubes: under 4x the light of 160";
}

TEST(NeonTubeLight, ThinTubesAreWidenedToTheMinimumOnScreen) {
  const float fov = kFovY;
  // 0.1 m at 26 m: about 4.3 px of radius at 1080p, kept; about 1.1 px at 270p, widened.
  EXPECT_EQ(drawnTubeRadius(0.1f, 26.0f, 1080.0f, fov), 0.1f);
  EXPECT_NEAR(tubeRadiusPixels(0.1f, 26.0f, 1080.0f, fov), 4.46f, 0.05f);
  const float small = drawnTubeRadius(0.1f, 26.0f, 270.0f, fov);
  EXPECT_GT(small, 0.1f);
  EXPECT_NEAR(tubeRadiusPixels(small, 26.0f, 270.0f, fov), kMinTubeRadiusPixels, 1e-4f);
}

}  // namespace
}  // namespace vitrine::neon
