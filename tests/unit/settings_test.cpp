// The settings file: a save/load round trip, values checked by the same table as --set, and hostile
// files that must neither crash the gallery nor lose the user's file.
#include "core/error.h"
#include "params/settings_file.h"
#include "support/files.h"
#include "support/scoped_env.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdlib>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <unistd.h>

namespace vitrine::params {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

enum class Tier { Auto, High, Low };

struct Kifs {
  int step = 9;
  Tier tier = Tier::High;
  float targetMs = 8.0f;
  float drag = 0.0f;
  bool grain = true;
  std::string label = "a";
};

const Schema& kifsSchema() {
  static const Schema schema = [] {
    auto s = Schema::forStruct<Kifs>();
    s.add(intParam({.key = "step"}, &Kifs::step, 1, 9));
    s.add(choiceParam({.key = "tier"}, &Kifs::tier, {"auto", "high", "low"}));
    s.add(floatParam({.key = "target_ms"}, &Kifs::targetMs, 0.1, 1000.0));
    s.add(floatParam({.key = "drag", .flags = kTransient}, &Kifs::drag, -100.0, 100.0));
    s.add(boolParam({.key = "grain"}, &Kifs::grain));
    s.add(customParam<Kifs, std::string>(
        {.key = "label"}, &Kifs::label,
        [](std::string_view text, std::string& value, std::string* error) {
          if (text.empty() || text.size() > 8) return *error = "expected 1 to 8 characters", false;
          value = text;
          return true;
        },
        [](const std::string& value) { return value; }));
    return s;
  }();
  return schema;
}

const Schema* schemaFor(std::string_view scene) {
  static const Schema empty = Schema::forStruct<Kifs>();
  if (scene == "kifs") return &kifsSchema();
  if (scene == "plain") return &empty;  // a scene with no parameters
  return nullptr;
}

void writeAll(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
}

// A fresh folder per test, removed afterwards.
class SettingsFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / fmt::format("vitrine-settings-{}-{}", getpid(), test->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    path_ = dir_ / "settings.json";
  }
  void TearDown() override { fs::remove_all(dir_); }

  LoadResult load() { return loadSettings(path_, schemaFor); }

  // Files in the folder other than settings.json: where a bad file went.
  std::vector<fs::path> asideFiles() const {
    std::vector<fs::path> found;
    for (const auto& entry : fs::directory_iterator(dir_))
      if (entry.path().filename().string().rfind("settings.json.bad-", 0) == 0) found.push_back(entry.path());
    return found;
  }

  // Writes `text`, loads it, and checks that it was moved aside intact and that the defaults apply.
  void expectMovedAside(const std::string& text, const std::string& why) {
    writeAll(path_, text);
    const LoadResult result = load();
    ASSERT_EQ(result.warnings.size(), 1u) << why;
    EXPECT_NE(result.warnings[0].find("moved it to"), std::string::npos) << result.warnings[0];
    EXPECT_TRUE(result.settings.scenes.empty()) << why;
    EXPECT_TRUE(result.settings.scene.empty()) << why;
    EXPECT_FALSE(fs::exists(path_)) << why;
    const auto aside = asideFiles();
    ASSERT_EQ(aside.size(), 1u) << why;
    EXPECT_NE(result.warnings[0].find(aside[0].string()), std::string::npos) << result.warnings[0];
    EXPECT_EQ(test::readFile(aside[0]), text) << why;  // kept, byte for byte
    fs::remove(aside[0]);
  }

  fs::path dir_, path_;
};

TEST_F(SettingsFile, MissingFileIsDefaultsWithoutWarning) {
  const LoadResult result = load();
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_TRUE(result.settings.scene.empty());
  EXPECT_TRUE(result.settings.scenes.empty());
}

TEST_F(SettingsFile, RoundTripKeepsValuesAndLeavesTransientOut) {
  Kifs kifs;
  const Bound bound = bindSettings(kifsSchema(), kifs);
  ASSERT_EQ(applyValues(bound, {{"step", "3"}, {"tier", "low"}, {"target_ms", "0.1"}, {"drag", "4"}, {"grain", "off"},
                          {"label", "hello"}}),
            "");
  Settings settings;
  settings.scene = "kifs";
  settings.scenes["kifs"] = snapshot(bound);  // transient included on purpose: the save leaves it out
  saveSettings(dir_ / "sub" / "settings.json", settings, schemaFor);  // creates the folder
  path_ = dir_ / "sub" / "settings.json";

  const std::string text = test::readFile(path_);
  EXPECT_EQ(text.find("drag"), std::string::npos) << text;
  // Typed JSON: numbers, booleans and strings by kind.
  const auto json = nlohmann::json::parse(text);
  EXPECT_EQ(json["version"], 1);
  EXPECT_EQ(json["scene"], "kifs");
  EXPECT_TRUE(json["scenes"]["kifs"]["step"].is_number_integer());
  EXPECT_TRUE(json["scenes"]["kifs"]["target_ms"].is_number());
  EXPECT_EQ(json["scenes"]["kifs"]["target_ms"].dump(), "0.1");  // not 0.10000000149011612
  EXPECT_EQ(json["scenes"]["kifs"]["grain"], false);
  EXPECT_EQ(json["scenes"]["kifs"]["tier"], "low");
  EXPECT_EQ(json["scenes"]["kifs"]["label"], "hello");

  const LoadResult result = load();
  EXPECT_TRUE(result.warnings.empty()) << result.warnings[0];
  EXPECT_EQ(result.settings.scene, "kifs");
  Kifs loaded;
  ASSERT_EQ(applyValues(bindSettings(kifsSchema(), loaded), result.settings.scenes.at("kifs")), "");
  EXPECT_EQ(loaded.step, 3);
  EXPECT_EQ(loaded.tier, Tier::Low);
  EXPECT_EQ(loaded.targetMs, 0.1f);
  EXPECT_FALSE(loaded.grain);
  EXPECT_EQ(loaded.label, "hello");
  EXPECT_EQ(loaded.drag, 0.0f);
  EXPECT_EQ(snapshot(bindSettings(kifsSchema(), loaded), false), snapshot(bound, false));
}

TEST_F(SettingsFile, UnknownKeysAndScenesSurviveASave) {
  writeAll(path_, R"({"version": 1, "window": {"w": 1280, "h": 720}, "scene": "kifs",
    "scenes": {"glass": {"ior": 1.5, "deep": [1, [2, {"x": null}]]},
               "kifs": {"step": 4, "future_knob": "x"},
               "plain": {"old": 1}}})");
  LoadResult result = load();
  EXPECT_TRUE(result.warnings.empty()) << result.warnings[0];
  EXPECT_EQ(result.settings.scenes.at("kifs"), (KeyValues{{"step", "4"}}));
  EXPECT_TRUE(result.settings.scenes.at("plain").empty());

  result.settings.scenes["kifs"] = {{"step", "6"}};
  saveSettings(path_, result.settings, schemaFor);
  const auto json = nlohmann::json::parse(test::readFile(path_));
  EXPECT_EQ(json["window"], nlohmann::json::parse(R"({"w": 1280, "h": 720})"));
  EXPECT_EQ(json["scenes"]["glass"], nlohmann::json::parse(R"({"ior": 1.5, "deep": [1, [2, {"x": null}]]})"));
  EXPECT_EQ(json["scenes"]["kifs"]["future_knob"], "x");
  EXPECT_EQ(json["scenes"]["kifs"]["step"], 6);
  EXPECT_EQ(json["scenes"]["plain"]["old"], 1);
  // And again: a second load/save cycle changes nothing.
  const std::string first = test::readFile(path_);
  saveSettings(path_, load().settings, schemaFor);
  EXPECT_EQ(test::readFile(path_), first);
}

TEST_F(SettingsFile, BadValuesAreDroppedWithOneWarningEach) {
  struct Case {
    std::string json;  // the value of "step" / "target_ms" / ...
    std::string key;
    std::string why;
  };
  const std::vector<Case> cases = {
      {R"("NaN")", "target_ms", "expected a number, found string"},
      {R"("0.5")", "target_ms", "expected a number, found string"},
      {"1e308", "target_ms", "expected a number from 0.1 to 1000"},
      {"-1e308", "target_ms", "expected a number from 0.1 to 1000"},
      {"1e-300", "target_ms", "expected a number from 0.1 to 1000"},
      {"2000", "target_ms", "expected a number from 0.1 to 1000"},
      {"12", "step", "expected a whole number from 1 to 9"},
      {"3.5", "step", "expected a whole number from 1 to 9"},
      {"3.0", "step", "expected a whole number from 1 to 9"},  // as strict as --set step=3.0
      {"18446744073709551615", "step", "expected a whole number from 1 to 9"},
      {"true", "step", "expected a whole number, found boolean"},
      {"null", "step", "expected a whole number, found null"},
      {R"({"value": 3})", "step", "expected a whole number, found object"},
      {"[3]", "step", "expected a whole number, found array"},
      {R"("medium")", "tier", "expected one of: auto high low"},
      {"1", "tier", "expected a string, found number"},
      {R"("on")", "grain", "expected true or false, found string"},
      {"1", "grain", "expected true or false, found number"},
      {R"("")", "label", "expected 1 to 8 characters"},
      {"4", "drag", "not kept between runs"},
  };
  for (const Case& c : cases) {
    writeAll(path_, fmt::format(R"({{"version": 1, "scenes": {{"kifs": {{"step": 2, "{}": {}}}}}}})", c.key, c.json));
    const LoadResult result = load();
    ASSERT_EQ(result.warnings.size(), 1u) << c.json;
    const std::string& warning = result.warnings[0];
    EXPECT_NE(warning.find("kifs." + c.key + "=" + nlohmann::json::parse(c.json).dump() + ": " + c.why), std::string::npos) << warning;
    EXPECT_NE(warning.find(path_.string()), std::string::npos) << warning;
    // The bad value is gone (its default applies); the good one beside it stays.
    KeyValues expected = {{"step", "2"}};
    if (c.key == "step") expected.clear();
    EXPECT_EQ(result.settings.scenes.at("kifs"), expected) << c.json;
    EXPECT_TRUE(asideFiles().empty());
  }
}

// Whatever the file holds reaches the terminal as short, printable text: no escape sequences, no raw
// bytes above ASCII, no line of a megabyte.
TEST_F(SettingsFile, WarningsQuoteShortPrintableText) {
  const std::string big(100000, 'x');
  writeAll(path_, "{\"version\": 1, \"scene\": \"\\u001b]0;owned\\u0007\xc3\xa9" + big + "\", "
                  "\"scenes\": {\"kifs\": {\"tier\": \"\\u001b[2J\xc3\xa9" + big + "\"}}, "
                  "\"outputs\": {\"\\u001b[31m\xc3\xa9" + big + "\": 3}}");
  const LoadResult result = load();
  ASSERT_EQ(result.warnings.size(), 3u);
  for (const std::string& warning : result.warnings) {
    EXPECT_LT(warning.size(), 600u);
    for (const char c : warning)
      EXPECT_TRUE(static_cast<unsigned char>(c) >= 0x20 && static_cast<unsigned char>(c) < 0x7f)
          << "byte " << int(static_cast<unsigned char>(c)) << " in " << warning.substr(0, 200);
  }
}

TEST_F(SettingsFile, NumbersAreCanonicalised) {
  writeAll(path_, R"({"scenes": {"kifs": {"step": 3, "target_ms": 0.1000000001, "label": "x"}}})");
  const LoadResult result = load();
  EXPECT_TRUE(result.warnings.empty()) << result.warnings[0];
  EXPECT_EQ(result.settings.scenes.at("kifs"), (KeyValues{{"step", "3"}, {"target_ms", "0.1"}, {"label", "x"}}));
}

TEST_F(SettingsFile, MalformedTopLevelValuesWarn) {
  writeAll(path_, R"({"scene": 4, "scenes": {"kifs": [1, 2]}})");
  LoadResult result = load();
  ASSERT_EQ(result.warnings.size(), 2u);
  EXPECT_NE(result.warnings[0].find("scene: expected a string, found number"), std::string::npos) << result.warnings[0];
  EXPECT_NE(result.warnings[1].find("scenes.kifs is array, not an object"), std::string::npos) << result.warnings[1];

  writeAll(path_, R"({"scene": "nope", "scenes": "kifs"})");
  result = load();
  ASSERT_EQ(result.warnings.size(), 2u);
  EXPECT_NE(result.warnings[0].find("no scene 'nope'"), std::string::npos) << result.warnings[0];
  EXPECT_NE(result.warnings[1].find("scenes: expected an object"), std::string::npos) << result.warnings[1];
  EXPECT_TRUE(asideFiles().empty());
}

TEST_F(SettingsFile, UnreadableFilesAreMovedAsideNotDeleted) {
  expectMovedAside(R"({"version": 1, "scenes": {"kifs": {"step": 3)", "truncated");
  expectMovedAside("", "empty");
  const char binary[] = "\x7f" "ELF\x02\x01\x01\0\0\0\xff\xfe\x80\x81";
  expectMovedAside(std::string(binary, sizeof binary - 1), "binary");
  expectMovedAside(R"([{"version": 1}])", "a top-level array");
  expectMovedAside("42", "a number");
  expectMovedAside(R"({"scenes": {"kifs": {"target_ms": NaN}}})", "bare NaN");
  expectMovedAside(R"({"version": 2, "scenes": {}})", "a newer version");
  expectMovedAside(std::string(100000, '['), "deep arrays");
  std::string objects;
  for (int i = 0; i < 100000; ++i) objects += R"({"a":)";
  expectMovedAside(objects, "deep objects");
  // Complete and inside a valid object: kept as an unknown scene, it would overflow the stack on save.
  expectMovedAside(R"({"scenes": {"glass": )" + std::string(100000, '[') + std::string(100000, ']') + "}}",
                   "deep but complete");
  expectMovedAside(R"({"scenes": {}, "pad": ")" + std::string(kMaxSettingsBytes, ' ') + R"("})", "over 1 MiB");
}

// nlohmann's parser refuses a number no double holds with an exception of its own (out_of_range), not
// a parse error: it escaped as "unexpected error" and stopped the gallery and the kiosk on every start.
TEST_F(SettingsFile, AnOutOfRangeNumberAnywhereIsMovedAsideLikeAnyUnreadableFile) {
  expectMovedAside(R"({"version": 1, "scenes": {"kifs": {"step": 1e400}}})", "under a known key");
  expectMovedAside(R"({"version": 1, "window": {"zoom": -1e400}, "scenes": {}})", "under an unknown key");
  expectMovedAside(R"({"version": 1e400})", "as the version");
}

TEST_F(SettingsFile, AFileThatCannotBeOpenedIsMovedAside) {
  if (::geteuid() == 0) GTEST_SKIP() << "root opens a file without read permission";
  writeAll(path_, R"({"version": 1, "scene": "kifs"})");
  fs::permissions(path_, fs::perms::none);
  const LoadResult result = load();
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("cannot open it"), std::string::npos) << result.warnings[0];
  EXPECT_NE(result.warnings[0].find("moved it to"), std::string::npos) << result.warnings[0];
  EXPECT_FALSE(fs::exists(path_));
  EXPECT_EQ(asideFiles().size(), 1u);
  EXPECT_FALSE(result.readable);
}

// A settings file kept in a dotfiles folder and linked into ~/.config stays a link; the file it points
// to gets the new content (the rename happens beside the target, not over the link).
TEST_F(SettingsFile, ASymlinkedFileStaysALink) {
  fs::create_directories(dir_ / "dotfiles");
  const fs::path real = dir_ / "dotfiles" / "vitrine.json";
  writeAll(real, R"({"version": 1, "scene": "kifs"})");
  fs::create_symlink("dotfiles/vitrine.json", path_);  // relative, as `ln -s` usually makes them
  fs::create_symlink(path_, dir_ / "second-link.json");  // and a link to that link
  Settings settings = load().settings;
  settings.scenes["kifs"] = {{"step", "5"}};
  saveSettings(dir_ / "second-link.json", settings, schemaFor);
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir_ / "second-link.json")));
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(path_)));
  EXPECT_EQ(nlohmann::json::parse(test::readFile(real))["scenes"]["kifs"]["step"], 5);
  EXPECT_EQ(resolveLinks(dir_ / "second-link.json"), dir_ / "dotfiles" / "vitrine.json");
  // A dangling link: the save creates the file it names.
  fs::remove(real);
  saveSettings(path_, settings, schemaFor);
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(path_)));
  EXPECT_TRUE(fs::is_regular_file(real));
  // A loop of links is an error, not a hang.
  fs::create_symlink("loop-b", dir_ / "loop-a");
  fs::create_symlink("loop-a", dir_ / "loop-b");
  EXPECT_THROW(saveSettings(dir_ / "loop-a", settings, schemaFor), Error);
}

// Each scene's filter chain is kept whole, as written, and merged scene by scene.
TEST_F(SettingsFile, FilterChainsRoundTripAndMergeByScene) {
  Settings settings;
  settings.filters["kifs"] = nlohmann::ordered_json::parse(R"([{"file": "/f/invert.fs", "values": {"amount": "0.5"}}])");
  saveSettings(path_, settings, schemaFor);
  LoadResult result = load();
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_EQ(result.settings.filters, settings.filters);
  writeAll(path_, R"({"version": 1, "filters": {"kifs": {"file": "x.fs"}}})");
  result = load();
  EXPECT_TRUE(result.settings.filters.empty());
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("filters.kifs: expected an array"), std::string::npos) << result.warnings[0];

  Settings disk, ours;
  disk.filters["kifs"] = nlohmann::ordered_json::array({{{"file", "a.fs"}}});
  disk.filters["glass"] = nlohmann::ordered_json::array({{{"file", "b.fs"}}});
  ours.filters["noodles"] = nlohmann::ordered_json::array({{{"file", "c.fs"}}});
  SettingsChanges changed;
  changed.filters = {"kifs", "noodles"};  // kifs' chain taken away here, noodles' made
  const Settings merged = mergeSettings(disk, ours, changed);
  EXPECT_FALSE(merged.filters.contains("kifs"));
  EXPECT_EQ(merged.filters.at("glass"), disk.filters.at("glass"));
  EXPECT_EQ(merged.filters.at("noodles"), ours.filters.at("noodles"));
}

TEST(SettingsMerge, OnlyChangedKeysOverwriteWhatIsOnDisk) {
  Settings disk;
  disk.scene = "noodles";
  disk.scenes["kifs"] = {{"step", "2"}, {"tier", "low"}};
  disk.scenes["glass"] = {{"ior", "1.5"}};
  disk.unknown["window"] = {{"w", 1280}};
  Settings ours;
  ours.scene = "kifs";
  ours.scenes["kifs"] = {{"step", "7"}, {"tier", "high"}, {"grain", "off"}};
  SettingsChanges changed;
  changed.keys["kifs"] = {"step", "grain", "label"};  // label: changed, then gone from ours
  Settings merged = mergeSettings(disk, ours, changed);
  EXPECT_EQ(merged.scene, "noodles") << "the scene was not changed here";
  EXPECT_EQ(merged.scenes.at("kifs"), (KeyValues{{"step", "7"}, {"tier", "low"}, {"grain", "off"}}));
  EXPECT_EQ(merged.scenes.at("glass"), (KeyValues{{"ior", "1.5"}}));
  EXPECT_EQ(merged.unknown["window"]["w"], 1280);
  changed.scene = true;
  EXPECT_EQ(mergeSettings(disk, ours, changed).scene, "kifs");
  changed.all = true;
  EXPECT_EQ(mergeSettings(disk, ours, changed).scenes, ours.scenes) << "--reset-settings starts over";
}

// A check spanning two parameters (tier low needs step 5 or less), as a scene's checkParameters.
TEST(SettingsConflicts, OnlyTheValuesThatConflictAreDropped) {
  Kifs kifs;
  const Bound bound = bindSettings(kifsSchema(), kifs);
  const auto apply = [&](const KeyValues& values) {
    return applyValues(bound, values, [&] { return kifs.tier == Tier::Low && kifs.step > 5 ? std::string("tier low needs step <= 5") : std::string(); });
  };
  const FittedValues fitted =
      applyWhatFits({{"step", "8"}, {"target_ms", "20"}, {"tier", "low"}, {"grain", "off"}}, apply);
  EXPECT_EQ(fitted.why, "tier low needs step <= 5");
  EXPECT_EQ(fitted.dropped, (std::vector<std::string>{"tier=low"}));
  EXPECT_EQ(fitted.kept, (KeyValues{{"step", "8"}, {"target_ms", "20"}, {"grain", "off"}}));
  EXPECT_EQ(kifs.step, 8);
  EXPECT_EQ(kifs.targetMs, 20.0f) << "the valid values are kept, not replaced by the defaults";
  EXPECT_FALSE(kifs.grain);
  EXPECT_EQ(kifs.tier, Tier::High);

  // Values that fit are applied as they are, with nothing dropped.
  Kifs fresh;
  kifs = fresh;
  const FittedValues fine = applyWhatFits({{"step", "3"}, {"tier", "low"}}, apply);
  EXPECT_TRUE(fine.dropped.empty());
  EXPECT_EQ(kifs.step, 3);
  EXPECT_EQ(kifs.tier, Tier::Low);
}

TEST_F(SettingsFile, TwoBadFilesInOneSecondBothKept) {
  writeAll(path_, "garbage one");
  load();
  writeAll(path_, "garbage two");
  load();
  const auto aside = asideFiles();
  ASSERT_EQ(aside.size(), 2u);
  std::set<std::string> contents;
  for (const auto& path : aside) contents.insert(test::readFile(path));
  EXPECT_EQ(contents, (std::set<std::string>{"garbage one", "garbage two"}));
}

TEST_F(SettingsFile, NotARegularFileIsLeftAlone) {
  fs::create_directory(path_);
  LoadResult result = load();
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_NE(result.warnings[0].find("not a regular file"), std::string::npos) << result.warnings[0];
  EXPECT_TRUE(fs::is_directory(path_));
  EXPECT_TRUE(asideFiles().empty());
  // Saving over a folder fails with an error, not a crash.
  EXPECT_THROW(saveSettings(path_, Settings{}, schemaFor), Error);

  if (fs::exists("/dev/zero")) {
    result = loadSettings("/dev/zero", schemaFor);
    ASSERT_EQ(result.warnings.size(), 1u);
    EXPECT_NE(result.warnings[0].find("not a regular file"), std::string::npos);
    EXPECT_TRUE(fs::exists("/dev/zero"));
  }
}

TEST_F(SettingsFile, SaveFailsWithAnErrorWhereNoFolderCanBeMade) {
  writeAll(dir_ / "file", "x");
  EXPECT_THROW(saveSettings(dir_ / "file" / "settings.json", Settings{}, schemaFor), Error);
}

using test::ScopedEnv;

TEST(SettingsPath, FollowsTheXdgRules) {
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", "/tmp/xdg-config");
    ScopedEnv home("HOME", "/home/someone");
    EXPECT_EQ(defaultSettingsPath(), fs::path("/tmp/xdg-config/vitrine/settings.json"));
  }
  for (const char* ignored : {"", "relative/config", "./config"}) {
    ScopedEnv xdg("XDG_CONFIG_HOME", ignored);
    ScopedEnv home("HOME", "/home/someone");
    EXPECT_EQ(defaultSettingsPath(), fs::path("/home/someone/.config/vitrine/settings.json")) << ignored;
  }
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", nullptr);
    ScopedEnv home("HOME", "/home/someone");
    EXPECT_EQ(defaultSettingsPath(), fs::path("/home/someone/.config/vitrine/settings.json"));
  }
  {
    ScopedEnv xdg("XDG_CONFIG_HOME", nullptr);
    ScopedEnv home("HOME", nullptr);
    EXPECT_TRUE(defaultSettingsPath().empty());
  }
}

TEST(SettingsSaver, WritesOnceAfterChangesSettle) {
  SettingsSaver saver(std::chrono::seconds(1));
  const Clock::time_point t0{};
  EXPECT_FALSE(saver.due(t0 + std::chrono::seconds(10)));  // nothing changed
  // A slider dragged for two seconds: a change every frame, no save while it moves.
  for (int frame = 0; frame <= 120; ++frame) {
    const auto now = t0 + std::chrono::milliseconds(frame * 1000 / 60);
    saver.markDirty(now);
    EXPECT_FALSE(saver.due(now));
  }
  const auto last = t0 + std::chrono::seconds(2);
  EXPECT_FALSE(saver.due(last + std::chrono::milliseconds(999)));
  EXPECT_TRUE(saver.due(last + std::chrono::seconds(1)));
  EXPECT_FALSE(saver.due(last + std::chrono::seconds(2)));  // once
  EXPECT_FALSE(saver.dirty());
}

TEST(SettingsSaver, FlushReportsUnsavedChangesOnce) {
  SettingsSaver saver;
  EXPECT_FALSE(saver.flush());
  saver.markDirty(Clock::time_point{});
  EXPECT_TRUE(saver.dirty());
  EXPECT_TRUE(saver.flush());
  EXPECT_FALSE(saver.flush());
  EXPECT_FALSE(saver.due(Clock::time_point{} + std::chrono::hours(1)));
}

}  // namespace
}  // namespace vitrine::params
