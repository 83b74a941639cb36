#include "scenes/glass/studio.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <array>
#include <cmath>

namespace vitrine::glass {
namespace {

// Lights, by where they stand seen from the stone. Longitude 0 is the camera, +-pi straight ahead.
// Radiances are linear, 15-200x the cyclorama's brightest, as a studio's strobes are: at the diamond
// preset's exposure the room reads as a light grey and the lights clip to white, and a wavelength that
// misses a light's edge sees a small fraction of its neighbour's light, which is what makes fire.
constexpr std::array<StudioLight, 20> kLights{{
    // The key: a large softbox above the camera, a little to its left.
    {0.45f, 0.62f, 0.28f, 0.17f, 0.02f, {24.0f, 23.5f, 22.5f}},
    // The fill: a tall softbox low on the camera's right.
    {-0.95f, 0.22f, 0.17f, 0.22f, 0.02f, {9.0f, 9.0f, 9.2f}},
    // Two strip lights standing behind the stone, either side of the view, the cyclorama's rim lights.
    {kPi - 0.4f, 0.3f, 0.025f, 0.5f, 0.008f, {46.0f, 45.0f, 44.0f}},
    {-(kPi - 0.4f), 0.3f, 0.025f, 0.5f, 0.008f, {46.0f, 45.0f, 44.0f}},
    // A strip boom across the view just above the frame, and a floor strip just below it: what a stone
    // seen through (the seed's leaning exits look 20-30 degrees about the view) splits into colour.
    {kPi, 0.5f, 0.6f, 0.028f, 0.008f, {36.0f, 35.0f, 34.0f}},
    {kPi, -0.52f, 0.6f, 0.028f, 0.008f, {30.0f, 29.0f, 28.0f}},
    // Two small kickers low at the sides.
    {1.75f, 0.05f, 0.05f, 0.07f, 0.01f, {72.0f, 70.0f, 68.0f}},
    {-1.75f, 0.12f, 0.05f, 0.07f, 0.01f, {72.0f, 70.0f, 68.0f}},
    // A ring of six small spots 25 degrees about the camera: a brilliant returns light from about the
    // viewer, so these are the sparks its crown throws, each small enough for its spectrum to show.
    {0.44f, 0.0f, 0.022f, 0.022f, 0.006f, {120.0f, 118.0f, 115.0f}},
    {0.22f, 0.38f, 0.022f, 0.022f, 0.006f, {120.0f, 118.0f, 115.0f}},
    {-0.22f, 0.38f, 0.022f, 0.022f, 0.006f, {120.0f, 118.0f, 115.0f}},
    {-0.44f, 0.0f, 0.022f, 0.022f, 0.006f, {120.0f, 118.0f, 115.0f}},
    {-0.22f, -0.38f, 0.022f, 0.022f, 0.006f, {120.0f, 118.0f, 115.0f}},
    {0.22f, -0.38f, 0.022f, 0.022f, 0.006f, {120.0f, 118.0f, 115.0f}},
    // Six short, thin light tubes right behind the stone, 6 degrees apart: seen through the stone, where
    // the seed's leaning exits look, their crisp edges are what its per-wavelength paths split into
    // colour; short, so that the stone itself hides most of them from the camera.
    {kPi - 0.1f, 0.0f, 0.005f, 0.16f, 0.002f, {10.0f, 10.0f, 10.0f}},
    {kPi - 0.2f, 0.0f, 0.005f, 0.16f, 0.002f, {10.0f, 10.0f, 10.0f}},
    {kPi - 0.3f, 0.0f, 0.005f, 0.16f, 0.002f, {10.0f, 10.0f, 10.0f}},
    {-kPi + 0.1f, 0.0f, 0.005f, 0.16f, 0.002f, {10.0f, 10.0f, 10.0f}},
    {-kPi + 0.2f, 0.0f, 0.005f, 0.16f, 0.002f, {10.0f, 10.0f, 10.0f}},
    {-kPi + 0.3f, 0.0f, 0.005f, 0.16f, 0.002f, {10.0f, 10.0f, 10.0f}},
}};

constexpr glm::vec3 kWarmWhite{1.0f, 0.975f, 0.95f};  // the cyclorama's paint

float smoothstep(float edge0, float edge1, float x) {
  const float t = glm::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// 1 inside [-half, half], 0 beyond half + soft, a smooth step between.
float band(float x, float half, float soft) { return smoothstep(half + soft, half - soft, std::fabs(x)); }

}  // namespace

glm::vec2 equirectUv(glm::vec3 d, float rotation) {
  const float longitude = std::atan2(d.x, d.z) + rotation;
  const float u = longitude / (2.0f * kPi) + 0.5f;
  return {u - std::floor(u), std::acos(glm::clamp(d.y, -1.0f, 1.0f)) / kPi};
}

glm::vec3 equirectDirection(glm::vec2 uv) {
  const float longitude = (uv.x - 0.5f) * 2.0f * kPi, polar = uv.y * kPi;
  return {std::sin(polar) * std::sin(longitude), std::cos(polar), std::sin(polar) * std::cos(longitude)};
}


std::span<const StudioLight> studioLights() { return kLights; }

glm::vec3 studioRoom(glm::vec3 d) {
  const float elevation = std::asin(glm::clamp(d.y, -1.0f, 1.0f));
  const float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
  const float ahead = horizontal > 1e-6f ? -d.z / horizontal : 0.0f;  // cos of the angle from the view axis
  const float cyclorama = smoothstep(-0.35f, 0.25f, ahead);  // the sweep wraps ~105 degrees either side
  // The cyclorama: a floor that brightens toward the sweep, the brightest band just above it, then the
  // wall fading into the dark ceiling.
  const float sweep = elevation < 0.0f ? 0.32f + 0.26f * smoothstep(-0.6f, 0.0f, elevation)
                                       : 0.58f - 0.52f * smoothstep(0.0f, 0.4f, elevation);
  const float flags = elevation < 0.0f ? 0.12f : 0.025f;  // the camera's side: a dark floor and black flags
  return kWarmWhite * (flags + (sweep - flags) * cyclorama);
}

glm::vec3 studioRadiance(glm::vec3 d) {
  glm::vec3 light = studioRoom(d);
  const float elevation = std::asin(glm::clamp(d.y, -1.0f, 1.0f));
  const float longitude = std::atan2(d.x, d.z);
  const float across = std::cos(elevation);  // a degree of longitude is this many degrees of arc
  for (const StudioLight& l : kLights) {
    const float along = std::remainder(longitude - l.longitude, 2.0f * kPi) * across;
    const float cover = band(along, l.halfWidth, l.soft) * band(elevation - l.elevation, l.halfHeight, l.soft);
    light += cover * l.radiance;
  }
  return light;
}

}  // namespace vitrine::glass
