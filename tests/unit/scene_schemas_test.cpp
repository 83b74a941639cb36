// sceneSchemas() is the registry's list without the GPU code; the two lists must not drift apart, or
// a new scene's parameters would escape the fuzz targets that read values through sceneSchemas().
#include "scenes/scene.h"
#include "scenes/schemas.h"
#include "params/listing.h"

#include <gtest/gtest.h>

namespace vitrine {
namespace {

TEST(SceneSchemas, SameScenesAndSchemasAsTheRegistry) {
  const auto registry = sceneRegistry();
  const auto schemas = sceneSchemas();
  ASSERT_EQ(schemas.size(), registry.size());
  for (size_t i = 0; i < registry.size(); ++i) {
    EXPECT_EQ(schemas[i].name, registry[i].name) << i;
    EXPECT_EQ(schemas[i].schema, registry[i].schema) << registry[i].name;
  }
}

// --list-params reads on a terminal: no line past 160 characters, however long a choice list or a
// help text, and nothing cut away (every choice's name is still there).
TEST(SceneSchemas, ListingsFitATerminal) {
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
