#pragma once
// Which `for` loops have a trip count their text fixes: GLSL ES 1.0's loop form (its Appendix A), the
// one WebGL demands and most ISF files are written in. A counter declared in the loop's start from a
// constant, a test of it against a constant, a constant step, and a body that never writes it. The
// translation charges such a loop's whole trip count to the invocation's loop budget once, as it
// enters, instead of guarding each iteration, so the compiler still sees a fixed count and unrolls it.
#include "isf/isf_tokens.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace vitrine::isf {

// What the whole text says that a loop's form depends on: names a `#define NAME NUMBER` or
// `const TYPE NAME = NUMBER;` fixes; functions with an `out` or `inout` parameter and macros whose
// replacement assigns (a body that uses one may write its counter through it).
struct LoopFacts {
  std::map<std::string, double, std::less<>> constants;
  std::set<std::string, std::less<>> writingFunctions;
  std::set<std::string, std::less<>> writingMacros;
};
LoopFacts loopFacts(const std::vector<Token>& tokens);

struct BoundedLoop {
  int trips = 0;         // iterations at most, counted from the constants
  size_t bodyStart = 0;  // index of the body's opening '{'
  size_t bodyEnd = 0;    // index of its closing '}'
};

// tokens[forIndex] is the word `for`. A loop in the form above whose body is a block and whose trip
// count is at most maxTrips; nothing for every other loop (which the translation guards per iteration).
std::optional<BoundedLoop> boundedLoop(const std::vector<Token>& tokens, size_t forIndex, const LoopFacts& facts,
                                       int maxTrips);

// The most loop iterations one call of the function `entry` can run, all loops together, nested ones
// multiplied and calls followed, when every loop of the text has a fixed count (and no macro holds a
// loop or names a function); nothing otherwise. Counts past `cap` read as cap.
std::optional<long long> worstIterations(const std::vector<Token>& tokens, const LoopFacts& facts,
                                         std::string_view entry, long long cap);

}  // namespace vitrine::isf
