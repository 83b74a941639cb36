#pragma once
// The photo studio the diamond stands in, made by the program rather than fetched: a light seamless
// cyclorama behind the stone, a dark studio on the camera's side (the black flags a jeweller's
// photographer sets so facets show contrast), and small, very bright softboxes, spots and strip lights,
// so the facets throw white brilliance and, where a light's edge is split by wavelength, coloured fire.
// Pure maths; the scene bakes it into an equirectangular half-float panorama when it is chosen
// (`panorama=photo_studio`), so the shaders sample it as they sample any panorama.
//
// Directions are in the panorama's own frame: +y up, longitude 0 toward the camera (+z), so at
// rotation 0 the camera looks at longitude ±pi, the cyclorama.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <span>
#include <string_view>

namespace vitrine::glass {

inline constexpr float kPi = 3.14159265358979f;

inline constexpr std::string_view kStudioPanorama = "photo_studio";

// The original's equirectangular convention: longitude atan2(d.x, d.z) plus the rotation, u = longitude /
// (2 pi) + 1/2; v = acos(d.y) / pi, the zenith on the top row. World +y is up and +z points toward the
// camera, so an unturned panorama shows its u = 0 seam straight ahead. shaders/glass/frame.glsl's
// equirectUv mirrors it.
glm::vec2 equirectUv(glm::vec3 d, float rotation);
// The unit direction that panorama coordinates uv show with rotation 0 (the inverse of equirectUv).
glm::vec3 equirectDirection(glm::vec2 uv);

// A rectangle of light on the studio's sphere: centred at (longitude, elevation), half sizes in radians of
// longitude and elevation, with a soft edge of `soft` radians so its border is smooth at the panorama's
// resolution, and its linear radiance.
struct StudioLight {
  float longitude, elevation;
  float halfWidth, halfHeight;
  float soft;
  glm::vec3 radiance;
};
std::span<const StudioLight> studioLights();

// The studio's room without its lights: the cyclorama (a light floor sweeping up into a wall that fades
// toward a dark ceiling) behind the stone, dark walls on the camera's side.
glm::vec3 studioRoom(glm::vec3 d);
// The whole studio's linear radiance along the unit direction d (panorama frame): the room and its lights.
glm::vec3 studioRadiance(glm::vec3 d);

}  // namespace vitrine::glass
