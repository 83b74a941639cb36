#pragma once
// The neon scene's building: a facade of axis-aligned boxes (world space, metres, y up; the facade's
// front plane at z = 0 facing +z, the ground's top at y = 0) and the soft lighting texture it samples
// through UVs projected along its normals. shaders/neon/facade_uv.glsl mirrors facadeUv.
#include "shaders/neon/facade_blocks.h"

#include <glm/common.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace vitrine::neon {

using Box = shader::NeonFacadeBox;  // the shader's: uploads as its std430 array as is

// The layout's numbers, for the camera and for tests.
inline constexpr float kFacadeHalfWidth = 10.0f;  // the front spans x in [-10, 10]
inline constexpr float kFacadeHeight = 20.0f;     // the wall's top; the cornice and roof plant rise above it
inline constexpr float kStorey = 4.0f;
inline constexpr int kStoreys = 5;
inline constexpr float kPillarX[] = {-9.4f, -4.7f, 0.0f, 4.7f, 9.4f};  // the outer two are flush with the sides
inline constexpr float kPillarHalfWidth = 0.6f;
inline constexpr float kRecessZ = -1.0f;  // the window glass: 1 m behind the front plane

// A camera that frames the front with the cornice in view and a strip of ground below it, low enough
// that the ground's reflection shows the ground floor: the facade's foot lands at about 0.79 of the
// frame's height (16:9). Checked by tests/unit/neon_look_test.cpp.
inline constexpr glm::vec3 kCameraEye{0.0f, 1.7f, 30.0f};
inline constexpr glm::vec3 kCameraTarget{0.0f, 8.0f, 0.0f};
inline constexpr float kCameraFovY = 0.8727f;  // radians (50 degrees), vertical

// The world box mapped once across the lighting texture by facadeUv (range (0, 1)): the facade's width
// and height, and the ground's depth. Matches facade_uv.glsl.
inline constexpr glm::vec3 kFacadeUvMin{-10.0f, 0.0f, -10.0f};
inline constexpr glm::vec3 kFacadeUvMax{10.0f, 20.0f, 40.0f};

// The building: ground slab (x in [-40, 40], z in [-10, 40], top at y = 0), the body behind the front,
// pillars standing 0.3 m proud, storey bands, ledges 0.55 m deep under every row of windows, a canopy
// over the ground floor, a cornice, mullions and transoms in the recessed windows, a pavement and a
// few boxes on the roof. Boxes may overlap; drawn as solids, overlaps are invisible.
std::vector<Box> facadeBoxes();

// The lighting the facade shows, `size` x `size` RGBA8, sRGB-encoded (upload as R8G8B8A8_SRGB), row 0
// at the top. Laid out for the front projection (u = x, v = height, upright): a cool sky-lit top, a warm
// street-lit bottom, pools of warm light under each ledge and the canopy, dark window recesses.
std::vector<uint8_t> facadeLightingTexture(uint32_t size);

// 1 when a > b, else 0, without a branch (the seed's when_gt).
inline float whenGt(float a, float b) { return 1.0f - glm::step(a, b); }

// Texture coordinates projected along the normal's dominant axis: (z, height) for faces along x,
// (x, z) for faces along y, (x, height) for faces along z. `range` is where the UV box's edges land
// in texture space ((0, 1): once across). Branchless, as the shader.
inline glm::vec2 facadeUv(glm::vec3 worldPos, glm::vec3 normal, glm::vec2 range) {
  glm::vec3 t = (worldPos - kFacadeUvMin) / (kFacadeUvMax - kFacadeUvMin);
  t.y = 1.0f - t.y;
  const glm::vec3 s = glm::mix(glm::vec3(range.x), glm::vec3(range.y), t);
  const glm::vec3 a = glm::abs(normal);
  glm::vec2 uv = glm::mix(glm::vec2(s.z, s.y), glm::vec2(s.x, s.z), glm::min(whenGt(a.y, a.x), whenGt(a.y, a.z)));
  uv = glm::mix(uv, glm::vec2(s.x, s.y), glm::min(whenGt(a.z, a.x), whenGt(a.z, a.y)));
  return uv;
}

// The ground's own light (linear RGB, before the facade's brightness scale), at a point of the ground
// or the pavement (the up-facing faces under kGroundTop): wet asphalt under a night sky, dark and a
// little blue, with the storefront's warm light spilling a few metres out from the building's foot.
// Smooth everywhere: the ground is not projected through the facade's lighting texture, whose windows
// it would print as a grid; what it shows besides this is the composite's mirror reflection.
// Mirrored by groundLight in shaders/neon/facade_uv.glsl.
inline constexpr float kGroundTop = 0.2f;  // up-facing faces below this are ground (the slab, the pavement)
inline glm::vec3 groundLight(glm::vec3 worldPos) {
  const glm::vec3 sky{0.010f, 0.012f, 0.022f};
  const glm::vec3 spill{0.26f, 0.13f, 0.05f};
  const float across = worldPos.x / 8.0f;
  const float away = std::max(worldPos.z, 0.0f) / 3.0f;  // metres in front of the facade, in falloffs
  return sky + spill * std::exp(-across * across - away);
}

}  // namespace vitrine::neon
