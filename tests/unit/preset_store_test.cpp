// The user's presets: saved, read back, renamed, deleted, exported and imported, every value checked as
// the settings file checks it, and every refusal with a reason naming the file or the name.
#include "host/gallery/gallery_settings.h"
#include "host/ui/param_panel.h"
#include "host/gallery/playlist.h"
#include "params/preset_store.h"
#include "scenes/catalogue.h"
#include "support/temp_folder.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <fstream>

namespace vitrine::params {
namespace {

namespace fs = std::filesystem;

class PresetStoreTest : public test::TempFolderTest {
 protected:
  fs::path presets() const { return folder_ / "presets"; }
  PresetStore open() const { return PresetStore(presets(), findSchema); }
  void write(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
  }
};

TEST_F(PresetStoreTest, ASavedPresetIsReadBackCanonicalByANewStore) {
  PresetStore store = open();
  ASSERT_EQ(store.save({"kifs", "evening glow", {{"step", "6"}, {"tier", "low"}}}), "");
  const PresetStore again = open();
  EXPECT_TRUE(again.warnings().empty());
  const UserPreset* read = again.find("kifs", "evening glow");
  ASSERT_NE(read, nullptr);
  EXPECT_EQ(read->values, (KeyValues{{"step", "6"}, {"tier", "low"}}));
  ASSERT_EQ(again.presetsOf("kifs").size(), 1u);
  EXPECT_TRUE(again.presetsOf("noodles").empty());
  EXPECT_TRUE(fs::exists(store.fileOf("kifs", "evening glow")));
  EXPECT_EQ(store.fileOf("kifs", "evening glow").filename(), "kifs-evening%20glow.json");
}

// A client saving under new names without end (every state message lists the presets) stops at the
// cap; saving again under a kept name, and other scenes, still work.
TEST_F(PresetStoreTest, NewNamesStopAtTheCapPerScene) {
  PresetStore store = open();
  std::string refused;
  for (int i = 0; i < 150 && refused.empty(); ++i)
    refused = store.save({"kifs", "look " + std::to_string(i), {{"step", "6"}}});
  EXPECT_NE(refused.find("as many as are kept"), std::string::npos) << refused;
  EXPECT_EQ(store.presetsOf("kifs").size(), 100u);
  EXPECT_EQ(std::distance(fs::directory_iterator(presets()), fs::directory_iterator()), 100);
  EXPECT_EQ(store.save({"kifs", "look 7", {{"step", "5"}}}), "");
  EXPECT_EQ(store.save({"bloom", "look 0", {}}), "");
}

TEST_F(PresetStoreTest, NamesThatClashOrCannotBeTypedAreRefusedWithAReason) {
  PresetStore store = open();
  EXPECT_NE(store.save({"kifs", "sphere", {{"step", "2"}}}).find("one of the scene's own presets"), std::string::npos);
  EXPECT_NE(store.save({"kifs", "", {{"step", "2"}}}).find("needs a name"), std::string::npos);
  EXPECT_NE(store.save({"kifs", "a\x01z", {{"step", "2"}}}).find("not printable"), std::string::npos);
  EXPECT_NE(store.save({"kifs", " lead", {{"step", "2"}}}).find("space"), std::string::npos);
  EXPECT_NE(store.save({"kifs", "kifs.x", {{"step", "2"}}}).find("'.'"), std::string::npos);
  EXPECT_NE(store.save({"kifs", std::string(41, 'x'), {{"step", "2"}}}).find("longer than 40"), std::string::npos);
  EXPECT_NE(store.save({"nowhere", "mine", {}}).find("no scene"), std::string::npos);
  EXPECT_TRUE(open().presetsOf("kifs").empty()) << "nothing refused was written";
}

TEST_F(PresetStoreTest, ValuesAreCheckedLikeSettingsBeforeSaving) {
  PresetStore store = open();
  const std::string why = store.save({"kifs", "mine", {{"step", "12"}}});
  EXPECT_NE(why.find("step=12"), std::string::npos) << why;
  EXPECT_NE(store.save({"kifs", "mine", {{"no_such_key", "1"}}}).find("no such parameter"), std::string::npos);
  EXPECT_EQ(store.find("kifs", "mine"), nullptr);
}

TEST_F(PresetStoreTest, RenameAndDeleteMoveAndRemoveTheFile) {
  PresetStore store = open();
  ASSERT_EQ(store.save({"kifs", "one", {{"step", "3"}}}), "");
  ASSERT_EQ(store.save({"kifs", "two", {{"step", "4"}}}), "");
  EXPECT_NE(store.rename("kifs", "one", "two").find("already has"), std::string::npos);
  EXPECT_NE(store.rename("kifs", "one", "final").find("own presets"), std::string::npos);
  EXPECT_NE(store.rename("kifs", "missing", "x").find("no preset of yours"), std::string::npos);
  ASSERT_EQ(store.rename("kifs", "one", "three"), "");
  EXPECT_FALSE(fs::exists(store.fileOf("kifs", "one")));
  ASSERT_EQ(store.remove("kifs", "two"), "");
  EXPECT_FALSE(fs::exists(store.fileOf("kifs", "two")));
  const PresetStore again = open();
  ASSERT_EQ(again.presetsOf("kifs").size(), 1u);
  EXPECT_EQ(again.presetsOf("kifs")[0]->name, "three");
  EXPECT_EQ(again.presetsOf("kifs")[0]->values, (KeyValues{{"step", "3"}}));
}

TEST_F(PresetStoreTest, ExportThenImportIsARoundTrip) {
  PresetStore store = open();
  ASSERT_EQ(store.save({"noodles", "thick", {{"grid", "16x16x4"}, {"integrator", "rk4"}}}), "");
  const fs::path exported = folder_ / "shared" / "thick.json";
  ASSERT_EQ(store.exportTo("noodles", "thick", exported), "");
  const PresetRead read = readPresetFile(exported, findSchema);
  ASSERT_TRUE(read.preset) << read.why;
  EXPECT_EQ(*read.preset, *store.find("noodles", "thick"));

  PresetStore elsewhere(folder_ / "other", findSchema);
  ASSERT_EQ(elsewhere.import(exported), "");
  EXPECT_EQ(*elsewhere.find("noodles", "thick"), *store.find("noodles", "thick"));
}

TEST_F(PresetStoreTest, BadFilesAreRefusedNamingTheFileAndMovedAsideNeverCrashing) {
  write(presets() / "kifs-good.json", R"({"version": 1, "scene": "kifs", "name": "good", "values": {"step": 2}})");
  write(presets() / "a.json", "{not json");
  write(presets() / "b.json", R"({"version": 1, "scene": "kifs", "name": "high", "values": {"step": 99}})");
  write(presets() / "c.json", R"({"version": 1, "scene": "kifs", "name": "sphere", "values": {"step": 2}})");
  write(presets() / "d.json", R"({"version": 1, "scene": "kifs", "name": "x", "values": {"bogus": 2}})");
  write(presets() / "e.json", R"({"version": 1, "scene": "nowhere", "name": "x", "values": {}})");
  write(presets() / "f.json", R"({"version": 7, "scene": "kifs", "name": "x", "values": {}})");
  write(presets() / "g.json", R"({"version": 1, "scene": "kifs", "name": "x", "values": {"step": "2"}})");
  write(presets() / "h.json", std::string(100000, '['));
  const PresetStore store = open();
  ASSERT_EQ(store.presetsOf("kifs").size(), 1u);
  EXPECT_EQ(store.presetsOf("kifs")[0]->name, "good");
  const std::vector<std::string> expected = {"not JSON", "step=99", "own presets", "bogus: no such parameter",
                                             "no scene 'nowhere'", "version 7", "expected a whole number",
                                             "larger than"};
  ASSERT_EQ(store.warnings().size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) {
    const std::string file = std::string(1, char('a' + i)) + ".json";
    EXPECT_NE(store.warnings()[i].find(file), std::string::npos) << store.warnings()[i];
    EXPECT_NE(store.warnings()[i].find(expected[i]), std::string::npos) << store.warnings()[i];
    EXPECT_FALSE(fs::exists(presets() / file)) << "moved aside";
  }
}

TEST_F(PresetStoreTest, ARunThatOnlyReadsLeavesABadFileWhereItIs) {
  write(presets() / "a.json", "{not json");
  const PresetStore store(presets(), findSchema, LoadMode::LeaveAlone);
  ASSERT_EQ(store.warnings().size(), 1u);
  EXPECT_NE(store.warnings()[0].find("left as it is"), std::string::npos) << store.warnings()[0];
  EXPECT_TRUE(fs::exists(presets() / "a.json"));
}

// The panel's list names the user's preset the values match, marked as theirs; a built-in match wins.
TEST_F(PresetStoreTest, ThePanelMarksTheUsersPresetThatTheValuesMatch) {
  const Schema& schema = *findSchema("kifs");
  const auto settings = schema.makeDefaults();
  const Bound bound{&schema, settings.get()};
  const UserPreset evening{"kifs", "evening", {{"step", "6"}, {"fold", "1.1"}}};
  const host::UserPresets mine{&evening};
  ASSERT_EQ(applyValues(bound, evening.values), "");
  EXPECT_EQ(host::matchingUserPreset(bound, mine), &evening);
  EXPECT_EQ(host::presetLabel(bound, mine), "evening (yours)");
  ASSERT_EQ(applyValues(bound, {{"fold", "1.2"}}), "");
  EXPECT_EQ(host::matchingUserPreset(bound, mine), nullptr);
  EXPECT_EQ(host::presetLabel(bound, mine), "custom");
  ASSERT_EQ(applyPreset(bound, "sphere"), "");
  const UserPreset sameAsSphere{"kifs", "mine", snapshot(bound, false)};
  EXPECT_EQ(host::presetLabel(bound, {&sameAsSphere}), "sphere");
}

TEST_F(PresetStoreTest, WithoutAFolderNothingIsSavedAndSaysWhy) {
  PresetStore store({}, findSchema);
  EXPECT_NE(store.save({"kifs", "mine", {{"step", "2"}}}).find("no settings folder"), std::string::npos);
}

}  // namespace
}  // namespace vitrine::params

namespace vitrine::host {
namespace {

const PlaylistChecks kChecks{
    [](std::string_view scene) { return scene == "kifs" || scene == "noodles"; },
    [](std::string_view scene, std::string_view name) {
      return scene == "kifs" && (name == "sphere" || name == "my evening look") ? std::string()
                                                                                 : "no preset '" + std::string(name) + "'";
    }};

TEST(Playlist, LinesGiveScenePresetAndDwell) {
  const auto entries = parsePlaylist("# programme\n\nkifs sphere 20\r\nnoodles 45.5\n  kifs my evening look  30\n",
                                     "p.txt", kChecks);
  const std::vector<PlaylistEntry> expected{
      {"kifs", "sphere", 20.0}, {"noodles", "", 45.5}, {"kifs", "my evening look", 30.0}};
  EXPECT_EQ(entries, expected);
}

TEST(Playlist, AByteOrderMarkIsNotPartOfTheFirstScene) {
  const auto entries = parsePlaylist("\xEF\xBB\xBFkifs sphere 20\nnoodles 5\n", "p.txt", kChecks);
  const std::vector<PlaylistEntry> expected{{"kifs", "sphere", 20.0}, {"noodles", "", 5.0}};
  EXPECT_EQ(entries, expected);
}

// What a playlist quotes back (a preset's name with an escape sequence, a name of a megabyte) reaches
// the terminal as short, plain text.
TEST(Playlist, RefusalsQuoteShortPrintableText) {
  for (const std::string& preset : {std::string("\x1b]0;owned\x07"), std::string("caf\xc3\xa9 \xff"),
                                   std::string(1 << 20, 'n')}) {
    try {
      parsePlaylist("kifs " + preset + " 10\n", "p.txt", kChecks);
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_LT(message.size(), 400u);
      for (const char c : message)
        EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f)
            << "byte " << int(static_cast<unsigned char>(c)) << " in " << message.substr(0, 200);
    }
  }
}

TEST(Playlist, TheFirstBadLineIsRefusedByNumber) {
  const auto refusal = [](std::string_view text) {
    try {
      parsePlaylist(text, "p.txt", kChecks);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("kifs 10\nglass 10\n"), "p.txt:2: no scene 'glass'; vitrine --list-scenes shows them.");
  EXPECT_EQ(refusal("kifs 10\n\nkifs nope 10\n"), "p.txt:3: no preset 'nope'.");
  EXPECT_NE(refusal("kifs sphere\n").find("p.txt:1: the dwell 'sphere'"), std::string::npos);
  EXPECT_NE(refusal("kifs 0\n").find("p.txt:1: the dwell '0'"), std::string::npos);
  EXPECT_NE(refusal("kifs -3\n").find("p.txt:1"), std::string::npos);
  EXPECT_NE(refusal("kifs 1e9\n").find("at most 86400"), std::string::npos);
  EXPECT_NE(refusal("kifs nan\n").find("p.txt:1"), std::string::npos);
  EXPECT_NE(refusal("kifs\n").find("p.txt:1: 'kifs' is not SCENE [PRESET] SECONDS"), std::string::npos);
  EXPECT_NE(refusal("kifs sp\x1bhere 3\n").find("control character"), std::string::npos);
  EXPECT_EQ(refusal("# nothing\n\n"), "p.txt: no entries; a line is SCENE [PRESET] SECONDS.");
}

TEST(Playlist, AMissingFileIsRefusedNamingIt) {
  try {
    loadPlaylist("/nonexistent/playlist.txt", kChecks);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/playlist.txt"), std::string::npos);
  }
}

}  // namespace
}  // namespace vitrine::host
