#pragma once
// Everything the noodles panel, "--set key=value" and the settings file can change, with the
// write-up's numbers as defaults where it has them. Parsing checks syntax and range only; whether the
// strands fit on the device is the scene's cross-parameter check (strand_layout.h).
#include "maths/flow_field.h"
#include "scenes/quality.h"
#include "scenes/noodles/field_bake.h"
#include "scenes/noodles/frames.h"
#include "scenes/noodles/integrate.h"
#include "scenes/noodles/palette.h"

#include "params/schema.h"
#include "scenes/catalogue.h"

#include <glm/vec3.hpp>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::noodles {

inline constexpr uint32_t kMaxGridSide = 4096;
inline constexpr int kMaxSegments = 4096;

// "orbit=AZIMUTH,ELEVATION,DISTANCE" pins the camera (reproducible views for tests and
// screenshots); "off" lets it fly.
struct OrbitPin {
  bool pinned = false;
  float azimuth = 0.0f, elevation = 0.0f, distance = 1.0f;  // radians, radians, world units
  bool operator==(const OrbitPin&) const = default;
};

struct NoodleSettings {
  glm::uvec3 grid{16, 16, 16};  // 4096 strands...
  int segments = 64;            // ...of 64 segments: 262,144 tube segments
  float step = 0.05f;
  float noiseScale = 0.5f;
  float spacing = 0.3f;
  float radius = 0.02f;
  float speed = 1.0f;  // noise units per second that the potentials drift (the write-up's rate)
  float lift = 0.0f;   // uniform upward flow: 2 or so makes strands near-vertical, where frames differ
  maths::FieldKind field = maths::FieldKind::Curl;
  Integrator integrator = Integrator::Euler;
  TangentMode tangent = TangentMode::Raw;  // the write-up leaves the field unnormalised
  FrameMethod frames = FrameMethod::RotationMinimizing;
  FieldSource fieldSource = FieldSource::Auto;  // auto: bake the flow where that pays (field_bake.h)
  Colouring colour = Colouring::Gradient;
  bool stripe = false;  // paint one side of every tube, so the frames' twist shows
  bool msaa = true;
  bool occluders = true;  // big nests draw every fourth strand first and skip what those hide
  OrbitPin orbit;
  Tier tier = Tier::Auto;  // high: as set; medium, low: 0.7 and 0.5 render scale
  float targetMs = 16.0f;
};

// Every parameter of the scene, declared once (see params/schema.h).
const params::Schema& schema();
// What the scene is by name: its title, key, help line and actions, with the schema above.
extern const SceneInfo kSceneInfo;

// "16" (a cube), "64x64" (a sheet) or "32x32x8".
bool parseGrid(std::string_view text, glm::uvec3& grid, std::string* error);
std::string formatGrid(const glm::uvec3& grid);
bool parseOrbit(std::string_view text, OrbitPin& orbit, std::string* error);
std::string formatOrbit(const OrbitPin& orbit);

}  // namespace vitrine::noodles
