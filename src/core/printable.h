#pragma once
// Text from outside (a script's words, a library's complaint quoting a file) made safe to print in an
// error message: bytes that are not printable ASCII are written as \xNN, so a terminal never receives
// raw control bytes and a reader sees exactly which bytes were there. A long text is cut to its first
// kPrintableBytes bytes with its length said, so a name of a megabyte never makes a line of one.
#include <cstddef>
#include <string>
#include <string_view>

namespace vitrine {
inline constexpr size_t kPrintableBytes = 200;
std::string printable(std::string_view text);
// A library's message without the blanks and newlines around it, to quote inside a sentence.
std::string trimmed(std::string text);
}  // namespace vitrine
