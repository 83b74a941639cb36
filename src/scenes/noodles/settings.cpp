#include "scenes/noodles/settings.h"

#include "scenes/noodles/camera.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>

namespace vitrine::noodles {
namespace {

bool parseUnsigned(std::string_view text, uint32_t lo, uint32_t hi, uint32_t& out) {
  uint32_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi) return false;
  out = value;
  return true;
}

bool parseFinite(std::string_view text, float& out) {
  float value = 0.0f;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return false;
  out = value;
  return true;
}

}  // namespace

bool parseGrid(std::string_view text, glm::uvec3& grid, std::string* error) {
  glm::uvec3 parsed{1};
  int axis = 0;
  size_t begin = 0;
  while (true) {
    const size_t end = text.find('x', begin);
    if (axis == 3 || !parseUnsigned(text.substr(begin, end - begin), 1, kMaxGridSide, parsed[axis++])) {
      *error = fmt::format("expected N, WxH or WxHxD with sides from 1 to {}", kMaxGridSide);
      return false;
    }
    if (end == std::string_view::npos) break;
    begin = end + 1;
  }
  grid = axis == 1 ? glm::uvec3(parsed.x) : parsed;
  return true;
}

std::string formatGrid(const glm::uvec3& grid) { return fmt::format("{}x{}x{}", grid.x, grid.y, grid.z); }

bool parseOrbit(std::string_view text, OrbitPin& orbit, std::string* error) {
  if (text == "off") {
    orbit = OrbitPin{};
    return true;
  }
  float values[3];
  size_t begin = 0;
  for (int i = 0; i < 3; ++i) {
    const size_t end = i < 2 ? text.find(',', begin) : text.size();
    if (end == std::string_view::npos || !parseFinite(text.substr(begin, end - begin), values[i])) {
      *error = "expected off or AZIMUTH,ELEVATION,DISTANCE (radians, radians, world units)";
      return false;
    }
    begin = end + 1;
  }
  if (std::fabs(values[1]) > kMaxElevation || !(values[2] > 0.0f) || std::fabs(values[0]) > 1000.0f ||
      values[2] > 1000.0f) {
    *error = fmt::format("the elevation must lie within +-{}, the distance in (0, 1000] and the azimuth in +-1000",
                         kMaxElevation);
    return false;
  }
  orbit = {true, values[0], values[1], values[2]};
  return true;
}

std::string formatOrbit(const OrbitPin& orbit) {
  if (!orbit.pinned) return "off";
  return fmt::format("{},{},{}", orbit.azimuth, orbit.elevation, orbit.distance);
}

const params::Schema& schema() {
  using S = NoodleSettings;
  using params::kLogarithmic, params::kRebuilds, params::kTransient;
  static const params::Schema table = [] {
    auto s = params::Schema::forStruct<S>();
    s.add(params::customParam<S, glm::uvec3>(
        {"grid", "grid", "Seed points per axis: N (a cube), WxH (a sheet) or WxHxD; one strand each.", "strands",
         kRebuilds},
        &S::grid, parseGrid, formatGrid));
    s.add(params::intParam<S>({"segments", "segments", "Tube segments per strand.", "strands",
                               kRebuilds | kLogarithmic},
                              &S::segments, 1, kMaxSegments));
    s.add(params::floatParam<S>({"step", "step", "Integration step along the field, in noise units.", "strands",
                                 kLogarithmic},
                                &S::step, 0.0001, 1.0));
    s.add(params::floatParam<S>({"spacing", "spacing", "Distance between neighbouring seed points.", "strands",
                                 kLogarithmic},
                                &S::spacing, 0.001, 10.0));
    s.add(params::floatParam<S>({"noise_scale", "noise scale", "Spatial frequency of the noise potentials.",
                                 "field", kLogarithmic},
                                &S::noiseScale, 0.001, 10.0));
    s.add(params::floatParam<S>({"speed", "time speed", "How fast the potentials drift, noise units per second.",
                                 "field"},
                                &S::speed, 0.0, 10.0));
    s.audioMapping("audio.mid=speed:0.3:3 attack=0.1 release=0.6");
    s.add(params::floatParam<S>({"lift", "lift", "A uniform upward flow added to the field.", "field"}, &S::lift,
                                -10.0, 10.0));
    s.add(params::choiceParam<S>({"field", "field", "curl: divergence-free curl noise; bitangent: the cross "
                                  "product of two noise gradients.", "field"},
                                 &S::field, {"curl", "bitangent"}));
    s.add(params::choiceParam<S>({"integrator", "integrator", "Euler (the write-up's) or classic Runge-Kutta 4.",
                                  "field"},
                                 &S::integrator, {"euler", "rk4"}));
    s.add(params::choiceParam<S>({"tangent", "tangent", "Follow the raw field or its unit direction.", "field"},
                                 &S::tangent, {"normalized", "raw"}));
    s.add(params::choiceParam<S>({"field_source", "field source",
                                  "exact: every step evaluates the noise; baked: steps sample the flow baked "
                                  "into a volume each frame (within ~5 %, far cheaper); auto: baked for nests "
                                  "big enough that it pays (about 10^7 segments and up).", "field"},
                                 &S::fieldSource, {"auto", "exact", "baked"}));
    s.add(params::choiceParam<S>({"frames", "frames", "Tube frames: up-vector (twists and pinches) or "
                                  "rotation-minimising.", "tubes"},
                                 &S::frames, {"up", "rmf"}));
    s.add(params::floatParam<S>({"radius", "radius", "Tube radius, world units.", "tubes", kLogarithmic},
                                &S::radius, 0.0001, 1.0));
    s.add(params::choiceParam<S>({"colour", "colour", "Colour by strand index: gradient (deep blue to warm "
                                  "sand), hsv (a pastel hue per strand) or grey (the write-up's final look: "
                                  "grey to white).", "tubes"},
                                 &S::colour, {"gradient", "hsv", "grey"}));
    s.add(params::boolParam<S>({"stripe", "stripe", "Paint one side of every tube, so the frames' twist shows.",
                                "tubes"},
                               &S::stripe));
    s.add(params::choiceParam<S>({"msaa", "msaa",
                                  "Anti-aliasing: 4x casts four rays a pixel (the standard rotated grid) and "
                                  "averages them; off casts one, at the pixel centre.",
                                  "tubes", kRebuilds},
                                 &S::msaa, {"off", "4x"}));
    s.add(params::boolParam<S>({"occluders", "occluders first",
                                "Nests of 4 million segments and more draw every fourth strand first and then "
                                "skip the segments those hide whole tiles of: the same picture, faster. Off: one "
                                "pass over every segment.", "tubes"},
                               &S::occluders));
    s.add(params::customParam<S, OrbitPin>(
        {"orbit", "pinned orbit", "off, or AZIMUTH,ELEVATION,DISTANCE to hold the camera there.", "camera",
         kTransient},
        &S::orbit, parseOrbit, formatOrbit));
    s.preset({"dense", "A million segments: 64x64x16 strands of 16.", {{"grid", "64x64x16"}, {"segments", "16"}}});
    s.preset({"rising", "Strands carried upwards, striped, with rotation-minimising frames.",
              {{"lift", "2"}, {"stripe", "on"}, {"tangent", "normalized"}, {"frames", "rmf"}}});
    s.preset({"smooth", "RK4 along the unit direction.", {{"integrator", "rk4"}, {"tangent", "normalized"}}});
    s.preset({"seed", "The write-up's final look: strands seeded on one flat sheet, grey to white by index.",
              {{"grid", "32x1x32"}, {"segments", "128"}, {"colour", "grey"}}});
    addQualityParams<S>(s, "Render scale (every tier draws every strand, at the samples msaa asks for)", 16.0f);
    return s;
  }();
  return table;
}

constinit const SceneInfo kSceneInfo{"noodles", "Curl-noise noodles", 5, &schema,
    "Drag to orbit the camera."};

}  // namespace vitrine::noodles
