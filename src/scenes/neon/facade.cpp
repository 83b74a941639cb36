// The neon scene's building and its lighting texture; see facade.h.
#include "scenes/neon/facade.h"

#include <glm/exponential.hpp>

#include <algorithm>
#include <cmath>

namespace vitrine::neon {
namespace {

// Boxes are easier to lay out by their corners than by centre and half size.
Box corners(glm::vec3 lo, glm::vec3 hi) {
  return {.centre = glm::vec4((lo + hi) * 0.5f, 0.0f), .halfSize = glm::vec4((hi - lo) * 0.5f, 0.0f)};
}

// Window openings, the heights between a storey's ledge and the next storey's band.
constexpr float kBandBelow = 0.4f;  // a storey band reaches this far under the floor line...
constexpr float kBandAbove = 0.7f;  // ...and this far above it, where the ledge sits
constexpr float kLedgeThickness = 0.15f;
constexpr float kParapetBottom = 19.0f;  // the top storey's windows are shorter: an attic
constexpr float kStorefrontBottom = 0.5f, kStorefrontTop = 3.4f;

float windowBottom(int storey) { return storey * kStorey + kBandAbove + kLedgeThickness; }
float windowTop(int storey) { return storey + 1 == kStoreys ? kParapetBottom : (storey + 1) * kStorey - kBandBelow; }
float bayCentre(int bay) { return 0.5f * (kPillarX[bay] + kPillarX[bay + 1]); }

glm::vec3 linearToSrgb(glm::vec3 c) {
  c = glm::clamp(c, 0.0f, 1.0f);
  return glm::mix(c * 12.92f, 1.055f * glm::pow(c, glm::vec3(1.0f / 2.4f)) - 0.055f,
                  glm::vec3(glm::greaterThan(c, glm::vec3(0.0031308f))));
}

// A soft-edged 1D window: 1 inside [lo, hi], easing to 0 over `soft` outside it.
float inside(float x, float lo, float hi, float soft) {
  return glm::smoothstep(lo - soft, lo + soft, x) * (1.0f - glm::smoothstep(hi - soft, hi + soft, x));
}

// Light spilling down the wall from a fitting tucked under a ledge at height `ledge`: brightest just
// under it, fading downwards over about a metre and sideways over one, and cut off above the ledge,
// which shadows the wall over it.
float pool(float x, float y, float centreX, float ledge) {
  const float below = ledge - y;
  const float across = (x - centreX) / 1.1f;
  return glm::smoothstep(-0.05f, 0.05f, below) * std::exp(-std::max(below, 0.0f) / 0.9f - across * across);
}

}  // namespace

std::vector<Box> facadeBoxes() {
  std::vector<Box> boxes;
  const float w = kFacadeHalfWidth, h = kFacadeHeight;
  boxes.push_back(corners({-40.0f, -1.0f, -10.0f}, {40.0f, 0.0f, 40.0f}));       // the ground slab
  boxes.push_back(corners({-w, 0.0f, -12.0f}, {w, h, kRecessZ}));                // the body; its front is the glass
  boxes.push_back(corners({-12.0f, 0.0f, 0.0f}, {12.0f, 0.15f, 3.0f}));          // pavement
  boxes.push_back(corners({-w, 0.0f, kRecessZ}, {w, kStorefrontBottom, 0.1f}));  // plinth
  for (float x : kPillarX)
    boxes.push_back(corners({x - kPillarHalfWidth, 0.0f, kRecessZ}, {x + kPillarHalfWidth, h, 0.3f}));
  for (int storey = 1; storey < kStoreys; ++storey) {
    const float floorY = storey * kStorey;
    boxes.push_back(corners({-w, floorY - kBandBelow, kRecessZ}, {w, floorY + kBandAbove, 0.0f}));  // band
    boxes.push_back(corners({-w - 0.2f, floorY + kBandAbove, kRecessZ},                             // ledge
                            {w + 0.2f, floorY + kBandAbove + kLedgeThickness, 0.55f}));
  }
  boxes.push_back(corners({-w, kParapetBottom, kRecessZ}, {w, h, 0.0f}));                       // parapet
  boxes.push_back(corners({-w - 0.5f, h, -12.2f}, {w + 0.5f, h + 0.5f, 0.8f}));                 // cornice
  boxes.push_back(corners({-4.1f, kStorefrontTop, 0.0f}, {4.1f, kStorey - kBandBelow, 2.0f}));  // canopy

  // Window frames, just proud of the glass.
  const float frameFront = kRecessZ + 0.2f;
  for (int bay = 0; bay < 4; ++bay) {
    const float x = bayCentre(bay);
    for (int storey = 1; storey < kStoreys; ++storey)  // one mullion per window
      boxes.push_back(corners({x - 0.08f, windowBottom(storey), kRecessZ}, {x + 0.08f, windowTop(storey), frameFront}));
    for (float side : {-0.6f, 0.6f})  // the shopfront: three panes a bay
      boxes.push_back(
          corners({x + side - 0.06f, kStorefrontBottom, kRecessZ}, {x + side + 0.06f, kStorefrontTop, frameFront}));
  }
  for (int storey = 1; storey < kStoreys; ++storey) {  // transoms: a fanlight across the top third
    const float y = glm::mix(windowBottom(storey), windowTop(storey), 0.7f);
    boxes.push_back(corners({-w, y - 0.05f, kRecessZ}, {w, y + 0.05f, frameFront}));
  }

  // Plant on the roof, set back from the cornice: it breaks the skyline.
  boxes.push_back(corners({-6.5f, h, -6.0f}, {-3.5f, h + 2.2f, -3.0f}));  // water tank
  boxes.push_back(corners({3.0f, h, -4.0f}, {5.2f, h + 0.9f, -2.2f}));    // air handler
  boxes.push_back(corners({-1.0f, h, -9.0f}, {1.6f, h + 2.6f, -6.0f}));   // stair housing
  return boxes;
}

std::vector<uint8_t> facadeLightingTexture(uint32_t size) {
  std::vector<uint8_t> texels(size_t(size) * size * 4);
  const glm::vec3 skyCool{0.035f, 0.06f, 0.16f}, streetWarm{0.42f, 0.20f, 0.08f}, teal{0.03f, 0.14f, 0.16f};
  const glm::vec3 fitting{1.0f, 0.72f, 0.45f};  // warm white lamps
  for (uint32_t row = 0; row < size; ++row) {
    for (uint32_t col = 0; col < size; ++col) {
      // The texel's centre on the front, metres (the front projection's inverse).
      const float u = (col + 0.5f) / size, v = (row + 0.5f) / size;
      const float x = glm::mix(kFacadeUvMin.x, kFacadeUvMax.x, u);
      const float y = glm::mix(kFacadeUvMax.y, kFacadeUvMin.y, v);
      const float up = y / kFacadeHeight;

      // Sky light from above, street light from below, a cooler left side against a warmer right.
      glm::vec3 c = glm::mix(streetWarm, skyCool, glm::smoothstep(0.0f, 0.75f, up));
      c = glm::mix(c, teal, 0.45f * (1.0f - u) * up);
      const float dx = x / 6.0f, dy = y / 3.0f;
      c += glm::vec3(0.5f, 0.28f, 0.12f) * std::exp(-dx * dx - dy * dy);  // the street's glow at the foot

      // Pools under every ledge, one a bay, and two brighter ones under the canopy.
      float lamps = 0.0f;
      for (int storey = 1; storey < kStoreys; ++storey)
        for (int bay = 0; bay < 4; ++bay) lamps += 0.7f * pool(x, y, bayCentre(bay), storey * kStorey + kBandAbove);
      for (int bay = 1; bay < 3; ++bay) lamps += 1.2f * pool(x, y, bayCentre(bay), kStorefrontTop);
      c += fitting * lamps;

      // The recesses stay dark: only the glass (the body's front) shows here, the bands and pillars
      // never do, so darkening the openings' rectangles darkens just the glass.
      float recess = 0.0f;
      for (int bay = 0; bay < 4; ++bay) {
        const float across = inside(x, kPillarX[bay] + kPillarHalfWidth, kPillarX[bay + 1] - kPillarHalfWidth, 0.12f);
        for (int storey = 1; storey < kStoreys; ++storey)
          recess = std::max(recess, across * inside(y, windowBottom(storey), windowTop(storey), 0.12f));
        recess = std::max(recess, across * inside(y, kStorefrontBottom, kStorefrontTop, 0.12f));
      }
      c *= 1.0f - 0.75f * recess;

      const glm::vec3 encoded = linearToSrgb(c);
      uint8_t* texel = &texels[(size_t(row) * size + col) * 4];
      for (int i = 0; i < 3; ++i) texel[i] = uint8_t(std::lround(encoded[i] * 255.0f));
      texel[3] = 255;
    }
  }
  return texels;
}

}  // namespace vitrine::neon
