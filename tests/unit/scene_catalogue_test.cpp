// The scene catalogue (scenes/catalogue.h) and the factories (scenes/scene.h): two tables generated from
// one list, which must name the same scenes, so every scene a name reaches can be made.
#include "scenes/catalogue.h"
#include "scenes/scene.h"
#include "params/listing.h"

#include <gtest/gtest.h>

namespace vitrine {
namespace {

TEST(SceneCatalogue, EverySceneHasAFactoryAndEveryFactoryAScene) {
  const auto registry = sceneRegistry();
  const auto factories = sceneFactories();
  ASSERT_EQ(factories.size(), registry.size());
  for (size_t i = 0; i < registry.size(); ++i) {
    EXPECT_EQ(factories[i].name, registry[i].name) << i;
    EXPECT_NE(sceneFactory(registry[i]), nullptr) << registry[i].name;
  }
  const SceneInfo stranger{"stranger", "Stranger", 9, registry[0].builtInSchema, ""};
  EXPECT_EQ(sceneFactory(stranger), nullptr);
}

TEST(SceneCatalogue, FindsSchemasByName) {
  for (const SceneInfo& scene : sceneRegistry()) EXPECT_EQ(findSchema(scene.name), &scene.schema()) << scene.name;
  EXPECT_EQ(findSchema("nope"), nullptr);
  EXPECT_EQ(findSchema(""), nullptr);
}

// --list-params reads on a terminal: no line past 160 characters, however long a choice list or a
// help text, and nothing cut away (every choice's name is still there).
TEST(SceneCatalogue, ListingsFitATerminal) {
  for (const SceneInfo& scene : sceneRegistry()) {
    const std::string text = params::describeSchema(scene.name, scene.schema());
    size_t start = 0, widest = 0;
    while (start < text.size()) {
      const size_t end = text.find('\n', start);
      widest = std::max(widest, end - start);
      EXPECT_LE(end - start, 160u) << scene.name << ": " << text.substr(start, end - start);
      start = end + 1;
    }
    for (const params::Param& param : scene.schema().params())
      for (const std::string& choice : param.choices)
        EXPECT_NE(text.find(choice), std::string::npos) << scene.name << "." << param.key << ": " << choice;
  }
}

}  // namespace
}  // namespace vitrine
