#include "core/assets.h"

#include <gtest/gtest.h>

#include <fstream>

namespace vitrine::host {
namespace {

TEST(Assets, ReportsEachMissingAssetAndFindsPresentOnes) {
  const auto root = std::filesystem::temp_directory_path() / "vitrine-assets-test";
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root / "fonts");
  Assets empty(root);
  EXPECT_EQ(empty.missing().size(), 3u);  // two fonts and the panoramas
  EXPECT_FALSE(empty.font("Fraunces"));

  std::ofstream(root / "fonts" / "Fraunces.woff2") << "wOF2";
  std::filesystem::create_directories(root / "hdri");
  std::ofstream(root / "hdri" / "studio.exr") << "x";
  Assets some(root);
  EXPECT_TRUE(some.font("Fraunces"));
  EXPECT_EQ(some.panoramas().size(), 1u);
  ASSERT_EQ(some.missing().size(), 1u);
  EXPECT_NE(some.missing()[0].find("CormorantSC"), std::string::npos);
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace vitrine::host
