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
  EXPECT_EQ(empty.missing().size(), 5u);  // three fonts, the photos and the panoramas
  EXPECT_FALSE(empty.font("Fraunces"));

  std::ofstream(root / "fonts" / "Fraunces.woff2") << "wOF2";
  std::filesystem::create_directories(root / "hdri");
  std::ofstream(root / "hdri" / "studio.exr") << "x";
  std::filesystem::create_directories(root / "photos");
  std::ofstream(root / "photos" / "01-dune.JPG") << "x";  // extensions in any case
  std::ofstream(root / "photos" / "COPYRIGHT") << "x";    // not a picture
  Assets some(root);
  ASSERT_EQ(some.photos().size(), 1u);
  EXPECT_EQ(some.photos()[0].filename(), "01-dune.JPG");
  EXPECT_TRUE(some.font("Fraunces"));
  EXPECT_EQ(some.panoramas().size(), 1u);
  ASSERT_EQ(some.missing().size(), 2u);
  EXPECT_NE(some.missing()[0].find("FrauncesItalic"), std::string::npos);
  EXPECT_NE(some.missing()[1].find("CormorantSC"), std::string::npos);
  std::filesystem::remove_all(root);
}

// A file a user names either is the file, or becomes one "missing asset" line saying what stands in.
TEST(Assets, NamedFilesAreFoundOrReportedOnceWithTheirFallback) {
  const auto root = std::filesystem::temp_directory_path() / "vitrine-assets-named";
  std::filesystem::remove_all(root);
  std::filesystem::create_directories(root / "folder");
  std::ofstream(root / "sky.exr") << "x";
  Assets assets(root);
  const size_t expected = assets.missing().size();
  EXPECT_EQ(assets.file(root / "sky.exr", "the procedural sky"), root / "sky.exr");
  EXPECT_FALSE(assets.file(root / "nope.exr", "the procedural sky"));
  EXPECT_FALSE(assets.file(root / "nope.exr", "the procedural sky"));  // reported once
  EXPECT_FALSE(assets.file(root / "folder", "the procedural sky"));
  const auto missing = assets.missing();
  ASSERT_EQ(missing.size(), expected + 2);
  EXPECT_NE(missing[expected].find("nope.exr: not found; using the procedural sky"), std::string::npos);
  EXPECT_NE(missing[expected + 1].find("not a regular file"), std::string::npos);
  std::filesystem::remove_all(root);
}

}  // namespace
}  // namespace vitrine::host
