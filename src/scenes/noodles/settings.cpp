#include "scenes/noodles/settings.h"

#include "scenes/parameters.h"

#include <fmt/format.h>

namespace vitrine::noodles {
namespace {

template <typename Enum, size_t N>
bool parseEnum(std::string_view text, const std::array<const char*, N>& names, Enum& out, std::string* error) {
  int index = 0;
  if (!parseChoice(text, names, index, error)) return false;
  out = Enum(index);
  return true;
}

}  // namespace

bool parseGrid(std::string_view text, glm::uvec3& grid, std::string* error) {
  glm::uvec3 parsed{1};
  int axis = 0;
  size_t begin = 0;
  while (true) {
    const size_t end = text.find('x', begin);
    int side = 0;
    std::string why;
    if (axis == 3 || !parseInt(text.substr(begin, end - begin), 1, int(kMaxGridSide), side, &why)) {
      *error = fmt::format("expected N, WxH or WxHxD with sides from 1 to {}", kMaxGridSide);
      return false;
    }
    parsed[axis++] = uint32_t(side);
    if (end == std::string_view::npos) break;
    begin = end + 1;
  }
  grid = axis == 1 ? glm::uvec3(parsed.x) : parsed;
  return true;
}

bool parseOrbit(std::string_view text, float values[3], std::string* error) {
  size_t begin = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t end = i < 2 ? text.find(',', begin) : text.size();
    std::string why;
    if (end == std::string_view::npos || !parseFloat(text.substr(begin, end - begin), -1000.0f, 1000.0f, values[i], &why)) {
      *error = "expected off or AZIMUTH,ELEVATION,DISTANCE (radians, radians, world units)";
      return false;
    }
    begin = end + 1;
  }
  return true;
}

bool applyParameter(NoodleSettings& s, std::string_view key, std::string_view value, std::string* error) {
  if (key == "grid") return parseGrid(value, s.grid, error);
  if (key == "segments") return parseInt(value, 1, kMaxSegments, s.segments, error);
  if (key == "step") return parseFloat(value, 0.0001f, 1.0f, s.step, error);
  if (key == "noise_scale") return parseFloat(value, 0.001f, 10.0f, s.noiseScale, error);
  if (key == "spacing") return parseFloat(value, 0.001f, 10.0f, s.spacing, error);
  if (key == "radius") return parseFloat(value, 0.0001f, 1.0f, s.radius, error);
  if (key == "speed") return parseFloat(value, 0.0f, 10.0f, s.speed, error);
  if (key == "lift") return parseFloat(value, -10.0f, 10.0f, s.lift, error);
  if (key == "field") return parseEnum(value, kFieldNames, s.field, error);
  if (key == "integrator") return parseEnum(value, kIntegratorNames, s.integrator, error);
  if (key == "tangent") return parseEnum(value, kTangentNames, s.tangent, error);
  if (key == "frames") return parseEnum(value, kFrameNames, s.frames, error);
  if (key == "colour") return parseEnum(value, kColourNames, s.colour, error);
  if (key == "stripe") return parseBool(value, s.stripe, error);
  if (key == "msaa") {
    int index = 0;
    if (!parseChoice(value, kMsaaNames, index, error)) return false;
    s.msaa = index == 1;
    return true;
  }
  *error = "unknown parameter";
  return false;
}

std::vector<std::string> parameterNames() {
  return {"grid",    "segments", "step",   "noise_scale", "spacing", "radius", "speed", "lift",
          "field",   "integrator", "tangent", "frames",     "colour",  "stripe", "msaa",  "orbit"};
}

}  // namespace vitrine::noodles
