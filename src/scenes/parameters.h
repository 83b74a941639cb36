#pragma once
// Parsing helpers for Scene::setParameter: each checks the range and says what was expected.
#include <array>
#include <charconv>
#include <fmt/format.h>
#include <string>
#include <string_view>

namespace vitrine {

inline bool parseInt(std::string_view text, int lo, int hi, int& out, std::string* error) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value < lo || value > hi) {
    *error = fmt::format("expected a whole number from {} to {}", lo, hi);
    return false;
  }
  out = value;
  return true;
}

inline bool parseFloat(std::string_view text, float lo, float hi, float& out, std::string* error) {
  float value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !(value >= lo && value <= hi)) {
    *error = fmt::format("expected a number from {} to {}", lo, hi);
    return false;
  }
  out = value;
  return true;
}

inline bool parseBool(std::string_view text, bool& out, std::string* error) {
  if (text == "1" || text == "true" || text == "on") return out = true, true;
  if (text == "0" || text == "false" || text == "off") return out = false, true;
  *error = "expected on or off";
  return false;
}

template <size_t N>
bool parseChoice(std::string_view text, const std::array<const char*, N>& names, int& out, std::string* error) {
  for (size_t i = 0; i < N; ++i)
    if (text == names[i]) return out = int(i), true;
  *error = "expected one of:";
  for (const char* name : names) *error += std::string(" ") + name;
  return false;
}

}  // namespace vitrine
