#pragma once
// The secret every request and socket must carry (?token=...): 128 random bits from the kernel, as
// 32 hex digits, made fresh each run and printed only in the page's URL.
#include <string>
#include <string_view>

namespace vitrine::remote {

std::string makeAccessToken();  // throws std::runtime_error if the kernel gives no randomness
// Compares in time that depends on the lengths only, not on where the texts first differ.
bool tokensEqual(std::string_view given, std::string_view expected);
// The value of `name` in a request target's query ("/socket?token=ab&x=1" → "ab"); empty when absent.
// No percent-decoding: tokens are hex.
std::string_view queryValue(std::string_view target, std::string_view name);
// The target without its query: "/socket?token=ab" → "/socket".
std::string_view targetPath(std::string_view target);

}  // namespace vitrine::remote
