// The built-in photo studio and the equirectangular convention the panoramas are sampled with.
#include "maths/hash.h"
#include "scenes/glass/studio.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace vitrine::glass {
namespace {


glm::vec3 randomDirection(uint32_t i) {
  const float z = maths::hash01({i, 1u, 0u}) * 2.0f - 1.0f, a = maths::hash01({i, 2u, 0u}) * 2.0f * kPi;
  const float r = std::sqrt(std::max(1.0f - z * z, 0.0f));
  return {r * std::cos(a), z, r * std::sin(a)};
}

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

// The original samples its panoramas at longitude atan2(d.x, d.z) + rotation, u = longitude / 2pi + 1/2,
// the zenith on the top row: +z (toward the camera) is the panorama's middle, straight ahead its seam.
TEST(Equirect, TheOriginalsLongitudeConvention) {
  EXPECT_NEAR(equirectUv({0.0f, 0.0f, 1.0f}, 0.0f).x, 0.5f, 1e-6f);
  EXPECT_NEAR(equirectUv({1.0f, 0.0f, 0.0f}, 0.0f).x, 0.75f, 1e-6f);
  EXPECT_NEAR(equirectUv({-1.0f, 0.0f, 0.0f}, 0.0f).x, 0.25f, 1e-6f);
  const float ahead = equirectUv({0.0f, 0.0f, -1.0f}, 0.0f).x;
  EXPECT_TRUE(ahead < 1e-6f || ahead > 1.0f - 1e-6f) << ahead;
  EXPECT_NEAR(equirectUv({0.0f, 1.0f, 0.0f}, 0.0f).y, 0.0f, 1e-6f);
  EXPECT_NEAR(equirectUv({0.0f, -1.0f, 0.0f}, 0.0f).y, 1.0f, 1e-6f);
  EXPECT_NEAR(equirectUv({0.0f, 0.0f, 1.0f}, 0.5f * kPi).x, 0.75f, 1e-6f);  // turning adds longitude
}

TEST(Equirect, DirectionIsTheInverse) {
  for (uint32_t i = 0; i < 2000; ++i) {
    const glm::vec3 d = randomDirection(i);
    if (std::fabs(d.y) > 0.999f) continue;  // the poles have no longitude
    const glm::vec3 back = equirectDirection(equirectUv(d, 0.0f));
    ASSERT_NEAR(glm::distance(back, d), 0.0f, 1e-4f) << i;
    ASSERT_NEAR(glm::length(back), 1.0f, 1e-5f);
  }
}

// A high-dynamic-range studio: lights ~50x the room, a light cyclorama behind the stone, dark flags behind
// the camera, and every value finite and positive.
TEST(Studio, LightsAreFarBrighterThanTheLightRoom) {
  float brightestRoom = 0.0f, brightest = 0.0f;
  for (uint32_t i = 0; i < 20000; ++i) {
    const glm::vec3 d = randomDirection(i), c = studioRadiance(d);
    ASSERT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
    ASSERT_GT(std::min({c.r, c.g, c.b}), 0.0f);
    brightestRoom = std::max(brightestRoom, luminance(studioRoom(d)));
    brightest = std::max(brightest, luminance(c));
  }
  EXPECT_GT(brightestRoom, 0.5f);
  EXPECT_LT(brightestRoom, 1.0f);
  EXPECT_GT(brightest, 100.0f * brightestRoom);
}

TEST(Studio, TheCameraLooksAtTheLitCycloramaAndHasDarkFlagsBehindIt) {
  const glm::vec3 ahead = glm::normalize(glm::vec3(0.0f, 0.1f, -1.0f));  // what an unturned panorama shows behind the stone
  const glm::vec3 behind = glm::normalize(glm::vec3(0.0f, 0.1f, 1.0f));
  EXPECT_GT(luminance(studioRadiance(ahead)), 0.45f);
  EXPECT_LT(luminance(studioRoom(behind)), 0.05f);
  // Across the lower half of a 45-degree view at 16:9 the cyclorama's floor stays light (the room, lights
  // aside), and the wall above it darkens toward the top of the frame.
  for (float x = -0.7f; x <= 0.7f; x += 0.1f) {
    for (float y = -0.4f; y <= 0.0f; y += 0.1f)
      ASSERT_GT(luminance(studioRoom(glm::normalize(glm::vec3(x, y, -1.0f)))), 0.3f) << x << " " << y;
    EXPECT_LT(luminance(studioRoom(glm::normalize(glm::vec3(x, 0.4f, -1.0f)))), 0.2f) << x;
  }
}

TEST(Studio, EachLightIsSmallBrightAndWhereItSays) {
  ASSERT_GE(studioLights().size(), 5u);
  for (const StudioLight& l : studioLights()) {
    const float c = std::cos(l.elevation);
    const glm::vec3 centre{c * std::sin(l.longitude), std::sin(l.elevation), c * std::cos(l.longitude)};
    EXPECT_GT(luminance(studioRadiance(centre)), 8.0f) << l.longitude;
    EXPECT_LT(4.0f * l.halfWidth * l.halfHeight, 0.25f) << "a softbox, not a wall: " << l.longitude;
    EXPECT_LT(l.soft, 0.5f * std::min(l.halfWidth, l.halfHeight)) << "a crisp edge, for fire";
    // Just past the soft edge the light is gone: the room alone.
    const float past = l.halfHeight + l.soft + 0.01f;
    const float e = l.elevation + past, ce = std::cos(e);
    const glm::vec3 beside{ce * std::sin(l.longitude), std::sin(e), ce * std::cos(l.longitude)};
    bool lit = false;  // unless another light stands there
    for (const StudioLight& other : studioLights())
      lit = lit || (&other != &l && std::fabs(std::remainder(other.longitude - l.longitude, 2.0f * kPi)) <
                                        other.halfWidth + l.halfWidth + 0.1f);
    if (!lit) {
      EXPECT_NEAR(luminance(studioRadiance(beside)), luminance(studioRoom(beside)), 1e-4f) << l.longitude;
    }
  }
}

TEST(Studio, ContinuousAcrossThePanoramasSeam) {
  for (float y = -0.8f; y <= 0.8f; y += 0.2f) {
    const glm::vec3 left = glm::normalize(glm::vec3(-1e-4f, y, -1.0f)), right = glm::normalize(glm::vec3(1e-4f, y, -1.0f));
    EXPECT_NEAR(luminance(studioRadiance(left)), luminance(studioRadiance(right)), 1e-2f) << y;
  }
}

}  // namespace
}  // namespace vitrine::glass
