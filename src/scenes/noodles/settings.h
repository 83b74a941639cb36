#pragma once
// Everything the noodles panel and "--set key=value" can change, with the write-up's numbers as
// defaults where it has them. Parsing checks syntax and range only; whether the strands fit on the
// device is the scene's check (strand_layout.h).
#include "scenes/noodles/field.h"
#include "scenes/noodles/frames.h"
#include "scenes/noodles/integrate.h"
#include "scenes/noodles/palette.h"

#include <glm/vec3.hpp>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::noodles {

inline constexpr std::array<const char*, 2> kFieldNames = {"curl", "bitangent"};
inline constexpr std::array<const char*, 2> kIntegratorNames = {"euler", "rk4"};
inline constexpr std::array<const char*, 2> kTangentNames = {"normalized", "raw"};
inline constexpr std::array<const char*, 2> kFrameNames = {"up", "rmf"};
inline constexpr std::array<const char*, 2> kColourNames = {"gradient", "hsv"};
inline constexpr std::array<const char*, 2> kMsaaNames = {"off", "4x"};
inline constexpr std::array<const char*, 2> kStripeNames = {"off", "on"};

inline constexpr uint32_t kMaxGridSide = 4096;
inline constexpr int kMaxSegments = 4096;

struct NoodleSettings {
  glm::uvec3 grid{16, 16, 16};  // 4096 strands...
  int segments = 64;            // ...of 64 segments: 262,144 tube segments
  float step = 0.05f;
  float noiseScale = 0.5f;
  float spacing = 0.3f;
  float radius = 0.02f;
  float speed = 1.0f;  // noise units per second that the potentials drift (the write-up's rate)
  float lift = 0.0f;   // uniform upward flow: 2 or so makes strands near-vertical, where frames differ
  FieldKind field = FieldKind::Curl;
  Integrator integrator = Integrator::Euler;
  TangentMode tangent = TangentMode::Raw;  // the write-up leaves the field unnormalised
  FrameMethod frames = FrameMethod::RotationMinimizing;
  Colouring colour = Colouring::Gradient;
  bool stripe = false;  // paint one side of every tube, so the frames' twist shows
  bool msaa = true;
};

// Applies one "key=value"; false with the reason in *error when the key is unknown or the value bad.
bool applyParameter(NoodleSettings& settings, std::string_view key, std::string_view value, std::string* error);
std::vector<std::string> parameterNames();

// "16" (a cube), "64x64" (a sheet) or "32x32x8".
bool parseGrid(std::string_view text, glm::uvec3& grid, std::string* error);

// "orbit=AZIMUTH,ELEVATION,DISTANCE" (radians, radians, world units) pins the camera; "orbit=off"
// lets it fly again. Scene-side, since it is camera state rather than a setting.
bool parseOrbit(std::string_view text, float values[3], std::string* error);

}  // namespace vitrine::noodles
