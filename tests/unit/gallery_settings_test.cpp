// The gallery's per-scene values across a session and the settings file behind them, and every
// registered scene's parameter declarations.
#include "host/gallery/gallery_settings.h"
#include "scenes/scene.h"
#include "support/files.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <vector>

namespace vitrine::host {
namespace {

// Each test's own empty folder, removed afterwards (support/temp_folder.h).
class GallerySettingsFile : public test::TempFolderTest {};

TEST_F(GallerySettingsFile, ValuesSurviveASwitchAndARestartButTransientOnesOnlyTheSwitch) {
  const auto path = folder_ / "settings.json";
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
  EXPECT_EQ(test::readFile(path).find("drag_x"), std::string::npos) << "a cursor drag is not a setting";
  GallerySettings again(path, false);
  EXPECT_EQ(again.lastScene(), "kifs");
  EXPECT_EQ(again.valuesFor("kifs"), (params::KeyValues{{"step", "4"}, {"tier", "low"}}));
  EXPECT_TRUE(again.valuesFor("noodles").empty());
}

TEST_F(GallerySettingsFile, ResetStartsCleanAndABadFileIsAWarningNotAnError) {
  const auto path = folder_ / "settings.json";
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
  for (const auto& entry : std::filesystem::directory_iterator(folder_))
    movedAside += entry.path().filename().string().starts_with("settings.json.bad-");
  EXPECT_EQ(movedAside, 1u) << "a file that does not parse is kept, beside";
}

TEST_F(GallerySettingsFile, AnOutOfRangeNumberIsAWarningNotAnError) {
  const auto path = folder_ / "settings.json";
  std::ofstream(path) << R"({"version": 1, "scene": "kifs", "elsewhere": {"n": 1e400}})";
  GallerySettings settings(path, false);  // threw nlohmann's out_of_range: "unexpected error", every start
  ASSERT_EQ(settings.warnings().size(), 1u);
  EXPECT_NE(settings.warnings()[0].find("moved it to"), std::string::npos) << settings.warnings()[0];
  EXPECT_FALSE(std::filesystem::exists(path));
}

// The file edited into broken JSON while the gallery runs: the next save moves it aside, as a start
// does, before writing the gallery's values; nothing the user typed is lost.
TEST_F(GallerySettingsFile, AFileBrokenWhileRunningIsMovedAsideBeforeTheNextSave) {
  const auto path = folder_ / "settings.json";
  std::ofstream(path) << R"({"version": 1, "scene": "kifs", "scenes": {"kifs": {"step": 4}}})";
  GallerySettings settings(path, false);
  const std::string edited = R"({"version": 1, "scenes": {"kifs": {"step": 5,}})";  // a stray comma
  std::ofstream(path, std::ios::trunc) << edited;
  settings.remember("kifs", {{"step", "6"}}, GallerySettings::Clock::now());
  settings.flush();
  std::vector<std::filesystem::path> aside;
  for (const auto& entry : std::filesystem::directory_iterator(folder_))
    if (entry.path().filename().string().starts_with("settings.json.bad-")) aside.push_back(entry.path());
  ASSERT_EQ(aside.size(), 1u) << "the broken file was written over";
  EXPECT_EQ(test::readFile(aside[0]), edited);
  EXPECT_EQ(nlohmann::json::parse(test::readFile(path))["scenes"]["kifs"]["step"], 6);
  ASSERT_FALSE(settings.warnings().empty());
  EXPECT_NE(settings.warnings().back().find("moved it to"), std::string::npos) << settings.warnings().back();
}

// Two galleries on one file: each writes only what it changed, so neither undoes the other.
TEST_F(GallerySettingsFile, TwoGalleriesOnOneFileMergeKeyByKey) {
  const auto path = folder_ / "settings.json";
  std::ofstream(path) << R"({"version": 1, "scene": "kifs", "scenes": {"kifs": {"step": 4}}})";
  const auto now = GallerySettings::Clock::now();
  GallerySettings first(path, false), second(path, false);
  // The first moves kifs to step 6; the second touches noodles and shows it, and (like a switch
  // away from kifs) remembers every kifs value it holds, unchanged: default ones and step 4.
  first.remember("kifs", {{"step", "6"}}, now);
  first.flush();
  auto kifs = second.valuesFor("kifs");
  kifs.emplace_back("tier", "auto");
  second.remember("kifs", kifs, now);
  second.remember("noodles", {{"segments", "24"}}, now);
  second.showing("noodles", now);
  second.flush();
  const auto json = nlohmann::json::parse(test::readFile(path));
  EXPECT_EQ(json["scenes"]["kifs"]["step"], 6) << "the second gallery did not change step: " << json.dump();
  EXPECT_EQ(json["scenes"]["noodles"]["segments"], 24);
  EXPECT_EQ(json["scene"], "noodles");
}

// Each output's warp (projector setup's pin) is kept under its name; a second gallery that set up another
// output keeps the first's; an identity warp removes the entry; a warp that is not an object is a warning.
TEST_F(GallerySettingsFile, WarpsAreKeptPerOutputAndMerged) {
  const auto path = folder_ / "settings.json";
  std::ofstream(path) << R"({"version": 1, "outputs": {"left": {"turn": 180}, "broken": [1, 2]}})";
  const auto now = GallerySettings::Clock::now();
  GallerySettings first(path, false), second(path, false);
  ASSERT_EQ(first.warnings().size(), 1u);
  EXPECT_NE(first.warnings()[0].find("outputs.broken: expected an object"), std::string::npos) << first.warnings()[0];
  ASSERT_NE(first.warpFor("left"), nullptr);
  EXPECT_EQ((*first.warpFor("left"))["turn"], 180);
  EXPECT_EQ(first.warpFor("main"), nullptr);
  first.setWarp("main", nlohmann::ordered_json{{"mirror", true}}, now);
  first.flush();
  second.setWarp("left", nlohmann::ordered_json(), now);  // set up back to the whole frame
  second.setWarp("right", nlohmann::ordered_json{{"region", {0.5, 0, 1, 1}}}, now);
  second.flush();
  const auto json = nlohmann::json::parse(test::readFile(path));
  EXPECT_EQ(json["outputs"]["main"]["mirror"], true) << json.dump();
  EXPECT_EQ(json["outputs"]["right"]["region"][0], 0.5) << json.dump();
  EXPECT_FALSE(json["outputs"].contains("left")) << json.dump();
  EXPECT_FALSE(json["outputs"].contains("broken")) << json.dump();
}

// A kiosk cycles through the scenes; the scene the gallery starts with next time stays the user's.
TEST_F(GallerySettingsFile, AKioskKeepsTheGallerysLastScene) {
  const auto path = folder_ / "settings.json";
  std::ofstream(path) << R"({"version": 1, "scene": "glass"})";
  const auto now = GallerySettings::Clock::now();
  {
    GallerySettings kiosk(path, false, /*keepScene=*/true);
    kiosk.showing("neon", now);
    kiosk.remember("neon", {{"chains", "256"}}, now);
  }
  const auto json = nlohmann::json::parse(test::readFile(path));
  EXPECT_EQ(json["scene"], "glass");
  EXPECT_EQ(json["scenes"]["neon"]["chains"], 256);
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
