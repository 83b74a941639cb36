#pragma once
// A fuzz target's check of a parser's promise: when it does not hold, abort, so libFuzzer keeps the
// input as a crash (and the message says which promise broke).
#include <cstdio>
#include <cstdlib>

namespace vitrine::fuzz {

inline void require(bool condition, const char* promise) {
  if (condition) return;
  std::fprintf(stderr, "broken promise: %s\n", promise);
  std::abort();
}

}  // namespace vitrine::fuzz
