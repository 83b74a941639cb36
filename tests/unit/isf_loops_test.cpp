// Which loops' trip counts their text fixes (isf_loops.h): the count for each form GLSL ES 1.0 allows,
// and every way a loop falls outside it, which leaves it to the per-iteration guard.
#include "isf/isf_loops.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

namespace vitrine::isf {
namespace {

// The trip count of the first `for` in the text, or -1 when its count is not fixed.
int trips(const std::string& glsl, int maxTrips = 65536) {
  const std::vector<Token> tokens = tokenize(glsl);
  for (size_t i = 0; i < tokens.size(); ++i)
    if (tokens[i].text == "for") {
      const std::optional<BoundedLoop> loop = boundedLoop(tokens, i, loopFacts(tokens), maxTrips);
      if (loop) {
        EXPECT_EQ(tokens[loop->bodyEnd].text, "}");
      }
      return loop ? loop->trips : -1;
    }
  ADD_FAILURE() << "no loop in: " << glsl;
  return -2;
}

TEST(IsfLoops, CountsEachFormOfAFixedLoop) {
  EXPECT_EQ(trips("for (int i = 0; i < 6; ++i) { s += 1.0; }"), 6);
  EXPECT_EQ(trips("for (int i = 0; i <= 6; i++) { s += float(i); }"), 7);
  EXPECT_EQ(trips("for (int i = 10; i > 0; i--) { s += 1.0; }"), 10);
  EXPECT_EQ(trips("for (int i = 10; i >= -2; --i) { }"), 13);
  EXPECT_EQ(trips("for (int i = 0; i < 7; i += 2) { }"), 4);
  EXPECT_EQ(trips("for (int i = 9; i > 0; i -= 3) { }"), 3);
  EXPECT_EQ(trips("for (int i = 0; i != 9; i += 3) { }"), 3);
  EXPECT_EQ(trips("for (int i = 5; i < 2; ++i) { }"), 0);
  EXPECT_EQ(trips("for (highp int i = 0; i < 5; ++i) { }"), 5);
  EXPECT_EQ(trips("#define STEPS 8\nvoid f() { for (int i = 0; i < STEPS; ++i) { } }"), 8);
  EXPECT_EQ(trips("const int kSteps = 3;\nvoid f() { for (int i = 0; i < kSteps; ++i) { } }"), 3);
  EXPECT_EQ(trips("for (int i = 0; i < 0x10; ++i) { }"), 16);
  // A float counter's sums round: charged 8/7 of its count and one more.
  EXPECT_EQ(trips("for (float x = 0.0; x < 1.0; x += 0.25) { }"), 6);
}

TEST(IsfLoops, ReadingTheCounterLeavesTheCountFixed) {
  EXPECT_EQ(trips("for (int i = 0; i < 4; ++i) { if (i == 2) break; a[i] = i <= 1 ? 1.0 : 0.0; s.i = 3; }"), 4);
  EXPECT_EQ(trips("void g(inout int k) {}\nvoid f() { for (int i = 0; i < 4; ++i) { continue; } }"), 4);
}

TEST(IsfLoops, LeavesEveryOtherLoopToTheGuard) {
  EXPECT_EQ(trips("for (int i = 0; i < 6; ++i) { i = 3; }"), -1);
  EXPECT_EQ(trips("for (int i = 0; i < 6; ++i) { i += 1; }"), -1);
  EXPECT_EQ(trips("for (int i = 0; i < 6; ++i) { i++; }"), -1);
  EXPECT_EQ(trips("for (int i = 0; i < 6; ++i) { --i; }"), -1);
  EXPECT_EQ(trips("for (int i = 0; i < 6; ++i) { i <<= 1; }"), -1);
  EXPECT_EQ(trips("void g(inout int k) { k = 0; }\nvoid f() { for (int i = 0; i < 4; ++i) { g(i); } }"), -1);
  EXPECT_EQ(trips("#define BACK(k) k -= 1\nvoid f() { for (int i = 0; i < 4; ++i) { BACK(i); } }"), -1);
  EXPECT_EQ(trips("for (int i = 0; i < 4; ++i) {\n#define X 1\n}"), -1);
  EXPECT_EQ(trips("for (int i = 0; i < count; ++i) { }"), -1);            // a uniform's bound
  EXPECT_EQ(trips("for (int i = 0; i < 6; --i) { }"), -1);                // away from its bound
  EXPECT_EQ(trips("for (int i = 0; i != 10; i += 3) { }"), -1);           // steps over it
  EXPECT_EQ(trips("for (uint i = 5u; i >= 0u; --i) { }"), -1);            // wraps past 0
  EXPECT_EQ(trips("for (int i = 0; i < 100000; ++i) { }"), -1);           // more than the budget
  EXPECT_EQ(trips("for (int i = 0; i < 10; ++i) { }", 9), -1);
  EXPECT_EQ(trips("for (int i = 0; i < 6; ++i) s += 1.0;"), -1);          // no block
  EXPECT_EQ(trips("for (int i = 0, j = 0; i < 6; ++i) { }"), -1);
  EXPECT_EQ(trips("for (i = 0; i < 6; ++i) { }"), -1);                    // a counter from outside
  EXPECT_EQ(trips("for (int i = 0; i < 6; i *= 2) { }"), -1);
  EXPECT_EQ(trips("for (int i = 0; j < 6; ++i) { }"), -1);
  EXPECT_EQ(trips("for (int i = 010; i < 16; ++i) { }"), -1);            // octal: not read
  // A constant's name declared again (a parameter, a local) or written is no constant.
  EXPECT_EQ(trips("const int N = 4;\nvoid f(int N) { for (int i = 0; i < N; ++i) { } }"), -1);
  EXPECT_EQ(trips("const int N = 4;\nvoid f() { int N = 9; for (int i = 0; i < N; ++i) { N++; } }"), -1);
  EXPECT_EQ(trips("#define N 4\nint k = 0;\nvoid f() { for (int i = 0; i < N; ++i) { } }"), 4);
  EXPECT_EQ(trips("const int N = 4;\nint g() { return N; }\nvoid f() { for (int i = 0; i < N; ++i) { } }"), 4);
  // x + 1.0 == x at 2^24: as written it never ends.
  EXPECT_EQ(trips("for (float x = 16777216.0; x < 16777220.0; x += 1.0) { }"), -1);
}

// The worst case of main(): loops multiplied by what their bodies run, calls followed.
long long worst(const std::string& glsl) {
  const std::vector<Token> tokens = tokenize(glsl);
  return worstIterations(tokens, loopFacts(tokens), "main", 1 << 20).value_or(-1);
}

TEST(IsfLoops, TheWorstCaseFollowsNestsAndCalls) {
  const std::string fbm = "float fbm(vec2 p) { float s = 0.0; for (int i = 0; i < 6; ++i) { s += p.x; } return s; }\n";
  EXPECT_EQ(worst(fbm + "void main() { float a = fbm(vec2(0.0)) + fbm(vec2(1.0)); }"), 12);
  EXPECT_EQ(worst(fbm + "void main() { for (int k = 0; k < 4; k++) { fbm(vec2(0.0)); } }"), 4 * (1 + 6));
  EXPECT_EQ(worst("void main() { for (int i = 0; i < 3; i++) { for (int j = 0; j < 5; j++) { } } }"), 3 * (1 + 5));
  EXPECT_EQ(worst("void main() { gl_FragColor = vec4(1.0); }"), 0);
  // Overloads: the costlier.
  EXPECT_EQ(worst("float f(float x) { for (int i = 0; i < 2; ++i) { } return x; }\n"
                  "float f(vec2 x) { for (int i = 0; i < 9; ++i) { } return x.x; }\nvoid main() { f(1.0); }"),
            9);
  // Past the cap: the cap.
  EXPECT_EQ(worst("void main() { for (int i = 0; i < 4096; i++) { for (int j = 0; j < 4096; j++) { } } }"), 1 << 20);
}

TEST(IsfLoops, NoWorstCaseWhereALoopIsNotFixedOrIsHidden) {
  EXPECT_EQ(worst("void main() { while (true) { } }"), -1);
  EXPECT_EQ(worst("void g() { for (int i = 0; i < n; ++i) { } }\nvoid main() { g(); }"), -1);
  EXPECT_EQ(worst("#define LOOP for (int i = 0; i < 9; ++i) { }\nvoid main() { LOOP }"), -1);
  EXPECT_EQ(worst("float g() { for (int i = 0; i < 9; ++i) { } return 1.0; }\n#define G g()\nvoid main() { G; }"), -1);
  EXPECT_EQ(worst("void other() { }"), -1);  // no main
}

}  // namespace
}  // namespace vitrine::isf
