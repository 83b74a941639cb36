// sceneSchemas() is the registry's list without the GPU code; the two lists must not drift apart, or
// a new scene's parameters would escape the fuzz targets that read values through sceneSchemas().
#include "scenes/scene.h"
#include "scenes/schemas.h"

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

}  // namespace
}  // namespace vitrine
