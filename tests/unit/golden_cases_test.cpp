// Every scene has golden frames, and every golden case draws a scene that exists. The scenes are the
// registry's, generated from the one list in cmake/Scenes.cmake; the cases are tests/golden/cases.txt
// ("NAME SCENE WxH ..." lines, SCENE being a scene's name or isf:FILE, an ISF generator in tests/isf;
// "! NAME ..." lines change a case and name no scene).
#include "scenes/scene.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vitrine {
namespace {

struct GoldenCaseLine {
  std::string name;
  std::string scene;
  int line = 0;
};

std::vector<GoldenCaseLine> goldenCases() {
  const auto path = std::filesystem::path(VITRINE_GOLDEN_DIR) / "cases.txt";
  std::ifstream in(path);
  EXPECT_TRUE(in.is_open()) << "cannot read " << path;
  std::vector<GoldenCaseLine> cases;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    std::istringstream words(text.substr(0, text.find('#')));
    GoldenCaseLine c{{}, {}, line};
    if (!(words >> c.name) || c.name == "!") continue;
    words >> c.scene;
    cases.push_back(c);
  }
  return cases;
}

TEST(SceneRegistry, EverySceneHasAGoldenCase) {
  const auto cases = goldenCases();
  ASSERT_FALSE(cases.empty());
  for (const SceneInfo& info : sceneRegistry()) {
    const bool covered = std::any_of(cases.begin(), cases.end(), [&](const auto& c) { return c.scene == info.name; });
    EXPECT_TRUE(covered) << "scene '" << info.name << "' (cmake/Scenes.cmake) has no golden case in "
                         << "tests/golden/cases.txt: add one and render it with scripts/update-goldens '*"
                         << info.name << "*'";
  }
}

TEST(SceneRegistry, GoldenCasesNameOnlyListedScenes) {
  for (const auto& c : goldenCases()) {
    // "isf:FILE": an ISF generator of the project's own, tests/isf/FILE, drawn as a piece.
    if (c.scene.starts_with("isf:")) {
      const auto file = std::filesystem::path(VITRINE_GOLDEN_DIR).parent_path() / "isf" / c.scene.substr(4);
      EXPECT_TRUE(std::filesystem::is_regular_file(file))
          << "tests/golden/cases.txt:" << c.line << ": case '" << c.name << "' draws " << file << ", which is not there";
      continue;
    }
    EXPECT_NE(findScene(c.scene), nullptr)
        << "tests/golden/cases.txt:" << c.line << ": case '" << c.name << "' draws scene '" << c.scene
        << "', which is not in VITRINE_SCENES (cmake/Scenes.cmake)";
  }
}

}  // namespace
}  // namespace vitrine
