#include "app/values.h"

#include "core/error.h"
#include "scenes/catalogue.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

namespace vitrine {

std::optional<uint32_t> wholeNumber(std::string_view text, uint32_t min, uint32_t max) {
  uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < min || value > max) return std::nullopt;
  return uint32_t(value);
}

uint32_t parseWhole(std::string_view flag, std::string_view text, uint32_t min, uint32_t max) {
  if (const auto value = wholeNumber(text, min, max)) return *value;
  throw Error(fmt::format("{} expects a whole number from {} to {}, not '{}'.", flag, min, max, text));
}

double parseSeconds(std::string_view flag, std::string_view text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
    throw Error(fmt::format("{} expects a finite number of seconds, not '{}'.", flag, text));
  return value;
}

double parsePositive(std::string_view flag, std::string_view text, double max) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !(value > 0.0) || !(value <= max))
    throw Error(fmt::format("{} expects a number above 0 and at most {}, not '{}'.", flag, max, text));
  return value;
}

double parseNumberIn(std::string_view flag, const std::string& text, double lo, double hi) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !(v >= lo && v <= hi))
    throw Error(fmt::format("{} takes a number from {:g} to {:g}, not '{}'.", flag, lo, hi, text));
  return v;
}

double parseMetric(std::string_view flag, const std::string& text, double lo, double hi) {
  return parseNumberIn(fmt::format("compare {}", flag), text, lo, hi);
}

std::pair<uint32_t, uint32_t> parseRange(std::string_view text) {
  const auto colon = text.find(':');
  const auto a = colon == std::string_view::npos ? std::nullopt : wholeNumber(text.substr(0, colon), 0, kMaxWhole);
  const auto b = colon == std::string_view::npos ? std::nullopt : wholeNumber(text.substr(colon + 1), 0, kMaxWhole);
  if (!a || !b || *a >= *b)
    throw Error(fmt::format("--range expects FIRST:END, frames FIRST up to but not including END, not '{}'.", text));
  return {*a, *b};
}

namespace {

// "SCENE.NAME" or "NAME": split at the '.', which neither scene names nor keys contain. Nothing when
// either side is empty or there is a second '.'. An unknown scene is an error naming `flag` and `text`.
std::optional<SceneSetting> qualifiedName(std::string_view flag, std::string_view name, std::string_view text) {
  SceneSetting setting;
  if (const auto dot = name.find('.'); dot != std::string_view::npos) {
    setting.scene = name.substr(0, dot);
    name.remove_prefix(dot + 1);
    if (setting.scene.empty()) return std::nullopt;
    if (!findScene(setting.scene)) throw Error(unknownScene(setting.scene, fmt::format(" in {} {}", flag, text)));
  }
  if (name.empty() || name.find('.') != std::string_view::npos) return std::nullopt;
  setting.key = name;
  return setting;
}

}  // namespace

SceneSetting parseSet(std::string_view text) {
  const auto eq = text.find('=');
  std::optional<SceneSetting> setting;
  if (eq != std::string_view::npos) setting = qualifiedName("--set", text.substr(0, eq), text);
  if (!setting) throw Error(fmt::format("--set expects KEY=VALUE or SCENE.KEY=VALUE, not '{}'.", text));
  setting->value = text.substr(eq + 1);
  return *setting;
}

std::optional<FilterSetting> parseFilterSet(std::string_view text) {
  constexpr std::string_view kPrefix = "filter.";
  if (text.substr(0, kPrefix.size()) != kPrefix) return std::nullopt;
  const auto eq = text.find('=');
  const std::string_view name = text.substr(kPrefix.size(), eq == std::string_view::npos ? 0 : eq - kPrefix.size());
  const auto dot = name.find('.');
  if (eq == std::string_view::npos || dot == std::string_view::npos || dot == 0 || dot + 1 == name.size() ||
      name.find('.', dot + 1) != std::string_view::npos)
    throw Error(fmt::format("--set expects filter.NAME.KEY=VALUE for a filter's parameter (NAME: the filter's file "
                            "name without its extension), not '{}'.",
                            text));
  return FilterSetting{std::string(name.substr(0, dot)), std::string(name.substr(dot + 1)), std::string(text.substr(eq + 1))};
}

std::optional<std::pair<std::string, std::string>> parseTransitionSet(std::string_view text) {
  constexpr std::string_view kPrefix = "transition.";
  if (text.substr(0, kPrefix.size()) != kPrefix) return std::nullopt;
  const auto eq = text.find('=');
  const std::string_view key = text.substr(kPrefix.size(), eq == std::string_view::npos ? 0 : eq - kPrefix.size());
  if (eq == std::string_view::npos || key.empty() || key.find('.') != std::string_view::npos)
    throw Error(fmt::format("--set expects transition.KEY=VALUE for an input of the --transition, not '{}'.", text));
  return std::pair{std::string(key), std::string(text.substr(eq + 1))};
}

SceneSetting parsePreset(std::string_view text) {
  std::optional<SceneSetting> preset;
  if (text.find('=') == std::string_view::npos) preset = qualifiedName("--preset", text, text);
  if (!preset) throw Error(fmt::format("--preset expects NAME or SCENE.NAME, not '{}'.", text));
  return *preset;
}

std::string lowercase(std::string text) {
  for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace vitrine
