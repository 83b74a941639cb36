#include "lights/patch.h"

#include "core/bounded_file.h"
#include "core/error.h"
#include "isf/isf_json_place.h"
#include "lights/signals.h"
#include "live/mapping.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace vitrine::lights {
namespace {

using Json = nlohmann::json;

constexpr std::array<std::pair<std::string_view, FixtureType>, 4> kTypes{
    {{"rgb", FixtureType::Rgb}, {"rgbw", FixtureType::Rgbw}, {"dimmer", FixtureType::Dimmer}, {"pixels", FixtureType::Pixels}}};

int lineAt(std::string_view text, size_t offset) {
  offset = std::min(offset, text.size());
  return 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(offset), '\n'));
}

class Reader {
 public:
  Reader(std::string_view text, std::string name) : text_(text), name_(std::move(name)) {}

  [[noreturn]] void fail(const isf::JsonPath& path, const std::string& why) const {
    throw Error(fmt::format("{}:{}: {}", name_, lineOf(path), why));
  }
  int lineOf(const isf::JsonPath& path) const { return lineAt(text_, isf::jsonPlace(text_, path)); }

  int whole(const Json& value, const isf::JsonPath& path, std::string_view what, int lo, int hi) const {
    if (!value.is_number_integer() && !value.is_number_unsigned())
      fail(path, fmt::format("{} must be a whole number from {} to {}", what, lo, hi));
    const auto number = value.get<int64_t>();
    if (number < lo || number > hi) fail(path, fmt::format("{} {} is outside {}..{}", what, number, lo, hi));
    return int(number);
  }

  void onlyKeys(const Json& object, const isf::JsonPath& path, std::initializer_list<std::string_view> keys) const {
    for (const auto& [key, value] : object.items())
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) {
        isf::JsonPath at = path;
        at.emplace_back(key);
        std::string known;
        for (std::string_view k : keys) known += (known.empty() ? "" : ", ") + std::string(k);
        fail(at, fmt::format("unknown key '{}' (known: {})", key, known));
      }
  }

 private:
  std::string_view text_;
  std::string name_;
};

Fixture readFixture(const Reader& reader, const Json& json, size_t i) {
  const isf::JsonPath at{std::string("fixtures"), i};
  const auto path = [&](const char* key) {
    isf::JsonPath p = at;
    p.emplace_back(std::string(key));
    return p;
  };
  if (!json.is_object()) reader.fail(at, "a fixture is an object {\"type\", \"universe\", \"address\", \"signal\", ...}");
  reader.onlyKeys(json, at, {"name", "type", "universe", "address", "count", "signal", "index"});
  for (const char* key : {"type", "universe", "address", "signal"})
    if (!json.contains(key)) reader.fail(at, fmt::format("fixture {} has no \"{}\"", i + 1, key));
  Fixture fixture;
  fixture.line = reader.lineOf(at);
  fixture.name = json.value("name", fmt::format("fixture {}", i + 1));
  if (json.contains("name") && (!json["name"].is_string() || fixture.name.empty() || fixture.name.size() > 64))
    reader.fail(path("name"), "a fixture's name is text of 1 to 64 characters");
  const Json& type = json["type"];
  const auto known = type.is_string() ? std::find_if(kTypes.begin(), kTypes.end(), [&](const auto& t) { return t.first == type.get<std::string>(); })
                                      : kTypes.end();
  if (known == kTypes.end()) reader.fail(path("type"), fmt::format("unknown fixture type {} (known: rgb, rgbw, dimmer, pixels)", type.dump()));
  fixture.type = known->second;
  fixture.universe = uint32_t(reader.whole(json["universe"], path("universe"), "universe", 0, int(kMaxUniverse)));
  fixture.address = reader.whole(json["address"], path("address"), "address", 1, kUniverseChannels);
  if (json.contains("count")) {
    if (fixture.type != FixtureType::Pixels) reader.fail(path("count"), "\"count\" is a pixel strip's (type \"pixels\")");
    fixture.count = reader.whole(json["count"], path("count"), "a strip's pixel count", 1, kMaxPixels);
  } else if (fixture.type == FixtureType::Pixels) {
    reader.fail(at, fmt::format("a pixel strip needs \"count\", 1 to {} pixels", kMaxPixels));
  }
  const Json& signal = json["signal"];
  if (!signal.is_string() || std::find(kSignalNames.begin(), kSignalNames.end(), signal.get<std::string>()) == kSignalNames.end()) {
    std::string names;
    for (std::string_view n : kSignalNames) names += (names.empty() ? "" : ", ") + std::string(n);
    reader.fail(path("signal"), fmt::format("unknown signal {} (known: {})", signal.dump(), names));
  }
  fixture.signal = signal.get<std::string>();
  if (json.contains("index")) fixture.index = reader.whole(json["index"], path("index"), "index", 0, int(kMaxSignalColours) - 1);
  const int last = fixture.address + channels(fixture) - 1;
  if (last > kUniverseChannels)
    reader.fail(path("address"), fmt::format("{} takes channels {}..{} of universe {}: past {}", fixture.name, fixture.address,
                                             last, fixture.universe, kUniverseChannels));
  return fixture;
}

}  // namespace

int channels(const Fixture& fixture) {
  switch (fixture.type) {
    case FixtureType::Rgb: return 3;
    case FixtureType::Rgbw: return 4;
    case FixtureType::Dimmer: return 1;
    case FixtureType::Pixels: return 3 * fixture.count;
  }
  return 3;
}

Patch parsePatch(std::string_view text, const std::string& name) {
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::parse_error& e) {
    // nlohmann's message, "[json.exception.parse_error.101] parse error at line 3, column 20: REASON",
    // without its own place: the file's line is ours.
    const std::string what = e.what();
    const size_t column = what.find("column ");
    const size_t reason = column == std::string::npos ? std::string::npos : what.find(": ", column);
    throw Error(fmt::format("{}:{}: not JSON: {}", name, lineAt(text, e.byte > 0 ? e.byte - 1 : 0),
                            reason == std::string::npos ? what : what.substr(reason + 2)));
  }
  const Reader reader(text, name);
  if (!json.is_object()) reader.fail({}, "a patch is an object {\"fixtures\": [...], ...}");
  reader.onlyKeys(json, {}, {"grid", "master", "master_source", "blackout_source", "input", "olad", "fixtures"});
  Patch patch;
  if (json.contains("grid")) {
    const Json& grid = json["grid"];
    if (!grid.is_array() || grid.size() != 2) reader.fail({std::string("grid")}, "\"grid\" is [WIDTH, HEIGHT], the regions across and down");
    patch.gridWidth = reader.whole(grid[0], {std::string("grid"), size_t(0)}, "the grid's width", 1, kMaxGridSide);
    patch.gridHeight = reader.whole(grid[1], {std::string("grid"), size_t(1)}, "the grid's height", 1, kMaxGridSide);
  }
  if (json.contains("master")) {
    const Json& master = json["master"];
    if (!master.is_number() || !(master.get<double>() >= 0.0 && master.get<double>() <= 1.0))
      reader.fail({std::string("master")}, "\"master\" is the master dimmer, a number from 0 to 1");
    patch.master = master.get<float>();
  }
  for (auto [key, field] : {std::pair{"master_source", &patch.masterSource}, std::pair{"blackout_source", &patch.blackoutSource}}) {
    if (!json.contains(key)) continue;
    const Json& source = json[key];
    const std::string why = source.is_string() ? live::checkSourceName(source.get<std::string>()) : "a live source's name";
    if (!why.empty()) reader.fail({std::string(key)}, fmt::format("\"{}\" is a live source (docs/LIVE.md): {}", key, why));
    *field = source.get<std::string>();
  }
  if (json.contains("olad"))
    patch.oladPort = uint16_t(reader.whole(json["olad"], {std::string("olad")}, "olad's RPC port", 1, 65535));
  if (json.contains("input")) {
    const Json& input = json["input"];
    if (!input.is_array() || input.size() > 64) reader.fail({std::string("input")}, "\"input\" is a list of at most 64 universes");
    for (size_t i = 0; i < input.size(); ++i) {
      const auto universe = uint32_t(reader.whole(input[i], {std::string("input"), i}, "universe", 0, int(kMaxUniverse)));
      if (std::find(patch.input.begin(), patch.input.end(), universe) == patch.input.end()) patch.input.push_back(universe);
    }
  }
  const Json fixtures = json.value("fixtures", Json::array());
  if (!fixtures.is_array()) reader.fail({std::string("fixtures")}, "\"fixtures\" is a list of fixtures");
  if (fixtures.size() > kMaxFixtures)
    reader.fail({std::string("fixtures"), kMaxFixtures}, fmt::format("more than {} fixtures", kMaxFixtures));
  for (size_t i = 0; i < fixtures.size(); ++i) {
    Fixture fixture = readFixture(reader, fixtures[i], i);
    for (const Fixture& other : patch.fixtures) {
      const int a0 = fixture.address, a1 = a0 + channels(fixture) - 1;
      const int b0 = other.address, b1 = b0 + channels(other) - 1;
      if (other.universe == fixture.universe && a0 <= b1 && b0 <= a1)
        reader.fail({std::string("fixtures"), i},
                    fmt::format("{} (channels {}..{} of universe {}) overlaps {} (channels {}..{}, line {})", fixture.name, a0, a1,
                                fixture.universe, other.name, b0, b1, other.line));
    }
    patch.fixtures.push_back(std::move(fixture));
  }
  return patch;
}

Patch loadPatch(const std::filesystem::path& path) {
  std::string text;
  try {
    text = readBoundedFile(path, kMaxPatchBytes);
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("Cannot read the lights' patch {}: {}", path.string(), refused.why));
  }
  return parsePatch(text, path.string());
}

}  // namespace vitrine::lights
