#pragma once
// "1 frame", "2 frames": a count and its noun, for the status lines (nouns that add an s).
#include <cstdint>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace vitrine::host {

inline std::string counted(uint64_t n, std::string_view noun) { return fmt::format("{} {}{}", n, noun, n == 1 ? "" : "s"); }

}  // namespace vitrine::host
