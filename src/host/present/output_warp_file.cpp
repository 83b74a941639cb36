#include "host/present/output_warp_file.h"

#include "core/bounded_file.h"
#include "core/error.h"
#include "params/schema.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>


namespace vitrine::host {
namespace {

constexpr uintmax_t kMaxWarpFileBytes = 1 << 20;  // a warp is a few hundred bytes

using nlohmann::json;

float number(const json& value, std::string_view where, std::string_view key) {
  if (!value.is_number()) throw Error(fmt::format("{}: {} is a number, not {}", where, key, value.dump()));
  return value.get<float>();
}

glm::vec2 point(const json& value, std::string_view where, std::string_view key) {
  if (!value.is_array() || value.size() != 2)
    throw Error(fmt::format("{}: {} is a point [x, y], not {}", where, key, value.dump()));
  return {number(value[0], where, key), number(value[1], where, key)};
}

void refuseUnknown(const json& object, std::initializer_list<std::string_view> known, std::string_view where) {
  for (const auto& [key, value] : object.items())
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw Error(fmt::format("{}: unknown key \"{}\" (an output's warp has {})", where, key,
                              fmt::join(known, ", ")));
}

}  // namespace

maths::OutputWarp outputWarpFromJson(const json& in, std::string_view where) {
  if (!in.is_object()) throw Error(fmt::format("{}: an output's warp is a JSON object", where));
  refuseUnknown(in, {"turn", "mirror", "region", "corners", "blend"}, where);
  maths::OutputWarp warp;
  if (in.contains("turn")) {
    const float turn = number(in["turn"], where, "turn");
    if (turn != 0.0f && turn != 90.0f && turn != 180.0f && turn != 270.0f)
      throw Error(fmt::format("{}: turn is 0, 90, 180 or 270 (degrees clockwise), not {}", where, turn));
    warp.quarterTurns = int(turn) / 90;
  }
  if (in.contains("mirror")) {
    if (!in["mirror"].is_boolean()) throw Error(fmt::format("{}: mirror is true or false", where));
    warp.mirror = in["mirror"].get<bool>();
  }
  if (in.contains("region")) {
    const json& r = in["region"];
    if (!r.is_array() || r.size() != 4) throw Error(fmt::format("{}: region is [left, top, right, bottom]", where));
    warp.region = {number(r[0], where, "region"), number(r[1], where, "region"), number(r[2], where, "region"),
                   number(r[3], where, "region")};
  }
  if (in.contains("corners")) {
    const json& c = in["corners"];
    if (!c.is_array() || c.size() != 4)
      throw Error(fmt::format("{}: corners are four points: top-left, top-right, bottom-right, bottom-left", where));
    for (size_t i = 0; i < 4; ++i) warp.corners[i] = point(c[i], where, "corners");
  }
  if (in.contains("blend")) {
    const json& b = in["blend"];
    if (!b.is_object()) throw Error(fmt::format("{}: blend is an object", where));
    refuseUnknown(b, {"left", "top", "right", "bottom", "curve", "gamma"}, where);
    maths::EdgeBlend& e = warp.blend;
    for (auto [key, field] : {std::pair{"left", &e.left}, {"top", &e.top}, {"right", &e.right},
                              {"bottom", &e.bottom}, {"curve", &e.curve}, {"gamma", &e.gamma}})
      if (b.contains(key)) *field = number(b[key], where, key);
  }
  if (const std::string why = maths::checkWarp(warp); !why.empty()) throw Error(fmt::format("{}: {}", where, why));
  return warp;
}

json outputWarpToJson(const maths::OutputWarp& warp) {
  // Each float as the shortest decimal that reads back to it ("2.2", not 2.200000047683716).
  const auto n = [](float value) { return std::stod(params::formatFloat(value)); };
  const maths::EdgeBlend& b = warp.blend;
  json corners = json::array();
  for (const glm::vec2& c : warp.corners) corners.push_back({n(c.x), n(c.y)});
  return {{"turn", warp.quarterTurns * 90},
          {"mirror", warp.mirror},
          {"region", {n(warp.region.x), n(warp.region.y), n(warp.region.z), n(warp.region.w)}},
          {"corners", corners},
          {"blend", {{"left", n(b.left)}, {"top", n(b.top)}, {"right", n(b.right)}, {"bottom", n(b.bottom)},
                     {"curve", n(b.curve)}, {"gamma", n(b.gamma)}}}};
}

maths::OutputWarp readOutputWarp(const std::filesystem::path& file) {
  std::string text;
  try {
    text = readBoundedFile(file, kMaxWarpFileBytes);
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("Cannot read the output warp {}: {}", file.string(), refused.why));
  }
  const json parsed = json::parse(text, nullptr, false);
  if (parsed.is_discarded()) throw Error(fmt::format("{} is not JSON", file.string()));
  return outputWarpFromJson(parsed, file.string());
}

}  // namespace vitrine::host
