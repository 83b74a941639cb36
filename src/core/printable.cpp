#include "core/printable.h"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

namespace vitrine {

std::string printable(std::string_view text) {
  std::string out;
  for (const char c : text.substr(0, kPrintableBytes)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) out += c;
    else out += fmt::format("\\x{:02x}", byte);
  }
  if (text.size() > kPrintableBytes) out += fmt::format("... ({} bytes)", text.size());
  return out;
}

std::string trimmed(std::string text) {
  const auto blank = [](unsigned char c) { return std::isspace(c) != 0; };
  text.erase(text.begin(), std::find_if_not(text.begin(), text.end(), blank));
  text.erase(std::find_if_not(text.rbegin(), text.rend(), blank).base(), text.end());
  return text;
}

}  // namespace vitrine
