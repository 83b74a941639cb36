#pragma once
// The command line's value parsers: each checks one kind of value and, for anything else, throws a
// vitrine::Error naming the flag, what it expects and what it got.
#include "app/options.h"

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace vitrine {

inline constexpr uint32_t kMaxWhole = std::numeric_limits<uint32_t>::max();

// A whole number in [min, max]; nothing for anything else (a sign, a fraction, too many digits).
std::optional<uint32_t> wholeNumber(std::string_view text, uint32_t min, uint32_t max);
uint32_t parseWhole(std::string_view flag, std::string_view text, uint32_t min, uint32_t max = kMaxWhole);
double parseSeconds(std::string_view flag, std::string_view text);  // any finite number
// A finite number above 0 and at most max (frames a second, a film's seconds).
double parsePositive(std::string_view flag, std::string_view text, double max);
// A number in [lo, hi]: "--link-tempo takes a number from 20 to 999, not 'fast'."
double parseNumberIn(std::string_view flag, const std::string& text, double lo, double hi);
// A number in [lo, hi], as compare's metric takes it: "compare --lowpass takes a number from 0 to 4096".
double parseMetric(std::string_view flag, const std::string& text, double lo, double hi);
std::pair<uint32_t, uint32_t> parseRange(std::string_view text);  // "A:B": frames A up to, not including, B
SceneSetting parseSet(std::string_view text);     // [SCENE.]KEY=VALUE
// "filter.NAME.KEY=VALUE": nothing when `text` does not start with "filter."; else the setting, or an
// Error saying what the form is.
std::optional<FilterSetting> parseFilterSet(std::string_view text);
// "transition.KEY=VALUE", likewise.
std::optional<std::pair<std::string, std::string>> parseTransitionSet(std::string_view text);
SceneSetting parsePreset(std::string_view text);  // [SCENE.]NAME
std::string lowercase(std::string text);

}  // namespace vitrine
