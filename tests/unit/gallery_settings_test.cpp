// The gallery's per-scene values across a session and the settings file behind them, and every
// registered scene's parameter declarations.
#include "host/gallery_settings.h"
#include "scenes/scene.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace vitrine::host {
namespace {

std::filesystem::path freshFolder(const std::string& name) {
  const auto folder = std::filesystem::temp_directory_path() / ("vitrine-gallery-settings-" + name);
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(GallerySettings, ValuesSurviveASwitchAndARestartButTransientOnesOnlyTheSwitch) {
  const auto path = freshFolder("roundtrip") / "settings.json";
  const auto now = GallerySettings::Clock::now();
  {
    GallerySettings settings(path, false);
    EXPECT_TRUE(settings.warnings().empty());
    settings.remember("kifs", {{"step", "4"}, {"tier", "low"}, {"drag_x", "0.5"}}, now);
    settings.showing("kifs", now);
    EXPECT_EQ(settings.valuesFor("kifs"), (params::KeyValues{{"step", "4"}, {"tier", "low"}, {"drag_x", "0.5"}}));
    settings.tick(now);  // changes still settling: nothing written yet
    EXPECT_FALSE(std::filesystem::exists(path));
    settings.tick(now + std::chrono::seconds(2));
    EXPECT_TRUE(std::filesystem::exists(path));
  }
  EXPECT_EQ(read(path).find("drag_x"), std::string::npos) << "a cursor drag is not a setting";
  GallerySettings again(path, false);
  EXPECT_EQ(again.lastScene(), "kifs");
  EXPECT_EQ(again.valuesFor("kifs"), (params::KeyValues{{"step", "4"}, {"tier", "low"}}));
  EXPECT_TRUE(again.valuesFor("noodles").empty());
}

TEST(GallerySettings, ResetStartsCleanAndABadFileIsAWarningNotAnError) {
  const auto folder = freshFolder("hostile");
  const auto path = folder / "settings.json";
  std::ofstream(path) << R"({"version": 1, "scene": "kifs", "scenes": {"kifs": {"step": 42, "tier": "low"}}})";
  {
    GallerySettings settings(path, false);
    ASSERT_EQ(settings.warnings().size(), 1u);
    EXPECT_NE(settings.warnings()[0].find("step"), std::string::npos);
    EXPECT_EQ(settings.valuesFor("kifs"), (params::KeyValues{{"tier", "low"}}));
  }
  GallerySettings reset(path, true);
  EXPECT_TRUE(reset.valuesFor("kifs").empty());
  EXPECT_TRUE(reset.lastScene().empty());
  std::ofstream(path, std::ios::trunc) << "{\"version\": 1, \"scenes\": ";  // truncated
  GallerySettings truncated(path, false);
  EXPECT_EQ(truncated.warnings().size(), 1u);
  size_t movedAside = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    movedAside += entry.path().filename().string().starts_with("settings.json.bad-");
  EXPECT_EQ(movedAside, 1u) << "a file that does not parse is kept, beside";
}

// Declaration mistakes (a default out of its own range, a preset naming an unknown key) throw when a
// schema is first built: building every scene's schema here finds them before a user does.
TEST(SceneSchemas, EveryRegisteredSceneDeclaresItsParametersAndPresetsValidly) {
  for (const auto& info : sceneRegistry()) {
    const params::Schema* schema = nullptr;
    ASSERT_NO_THROW(schema = &info.schema()) << info.name;
    EXPECT_FALSE(schema->params().empty()) << info.name;
    for (const auto& param : schema->params()) EXPECT_FALSE(param.help.empty()) << info.name << "." << param.key;
    for (const auto& preset : schema->presets()) {
      const auto scratch = schema->makeDefaults();
      EXPECT_EQ(params::applyPreset({schema, scratch.get()}, preset.name), "") << info.name << " " << preset.name;
    }
  }
}

}  // namespace
}  // namespace vitrine::host
