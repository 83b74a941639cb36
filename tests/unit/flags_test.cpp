// The flag table (app/flags.h) and what is made from it: the parse knows every flag, each mode needs
// what its synopsis says it needs, --help names every flag and fits 100 columns, the man page and the
// completion script are made from the same declarations.
#include "app/flags.h"
#include "app/help.h"
#include "app/options.h"
#include "core/error.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine {
namespace {

std::string flagRefusal(std::vector<std::string> args) {
  std::vector<const char*> argv{"vitrine"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  try {
    parseOptions(int(argv.size()), argv.data());
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

// The shortest command line each checked mode accepts, with every flag its synopsis shows as needed.
struct MinimalRun {
  flags::ModeBit bit;
  std::vector<std::string> args;
};
const std::vector<MinimalRun>& minimalRuns() {
  static const std::vector<MinimalRun> runs{
      {flags::kGallery, {}},
      {flags::kHeadless, {"--headless", "--scene", "kifs", "--out", "x.exr"}},
      {flags::kRecord, {"record", "--scene", "kifs", "--seconds", "1", "--out", "frames"}},
      {flags::kBench, {"bench", "--json", "b.json"}},
      {flags::kCompare, {"compare", "a.exr", "b.exr"}},
      {flags::kExport, {"--export-preset", "kifs.x", "--out", "e.json"}},
  };
  return runs;
}

TEST(Flags, NamesAreUniqueAndEachHasHelpAndAStore) {
  std::set<std::string_view> names;
  for (const flags::Flag& flag : flags::table()) {
    EXPECT_TRUE(names.insert(flag.name).second) << flag.name << " declared twice";
    EXPECT_TRUE(flag.name.starts_with("--")) << flag.name;
    EXPECT_FALSE(flag.help.empty()) << flag.name;
    EXPECT_NE(flag.store, nullptr) << flag.name;
    EXPECT_NE(flag.modes, 0u) << flag.name;
    EXPECT_EQ(flag.metavar.empty(), flag.value == flags::Value::None) << flag.name << ": a value needs a metavariable";
    EXPECT_EQ(flag.requiredIn & ~flag.modes, 0u) << flag.name << " is required where it is not taken";
  }
}

TEST(Flags, EachModeAcceptsItsMinimalRunAndRefusesItWithoutANeededFlag) {
  for (const MinimalRun& run : minimalRuns()) {
    EXPECT_EQ(flagRefusal(run.args), "accepted") << flags::modeTitle(run.bit);
    for (const flags::Flag& flag : flags::table()) {
      if (!(flag.requiredIn & run.bit)) continue;
      std::vector<std::string> without;
      for (size_t i = 0; i < run.args.size(); ++i) {
        if (run.args[i] == flag.name) i += flag.value == flags::Value::None ? 0 : 1;  // and its value
        else without.push_back(run.args[i]);
      }
      ASSERT_NE(without.size(), run.args.size()) << flags::modeTitle(run.bit) << "'s minimal run lacks " << flag.name;
      EXPECT_NE(flagRefusal(without), "accepted") << flags::modeTitle(run.bit) << " without " << flag.name;
    }
  }
}

// Every switch is refused in each checked mode it does not belong to, naming the modes it does.
TEST(Flags, ASwitchOutsideItsModesIsRefusedNamingThem) {
  int refused = 0;
  for (const MinimalRun& run : minimalRuns())
    for (const flags::Flag& flag : flags::table()) {
      if (flag.value != flags::Value::None || (flag.modes & (run.bit | flags::kListing)) || flag.name == "--headless")
        continue;
      std::vector<std::string> args = run.args;
      args.emplace_back(flag.name);
      EXPECT_EQ(flagRefusal(args), fmt::format("{} is only for {}, not {}.", flag.name, flags::modeList(flag.modes),
                                           flags::modeTitle(run.bit)));
      ++refused;
    }
  EXPECT_GT(refused, 40);
}

TEST(Flags, OnlyTheRepeatableRepeat) {
  EXPECT_EQ(flags::repeatableList(), "--isf, --set, --filter, --preset, --preset-file, --map and --remote-allow");
  EXPECT_EQ(flagRefusal({"--headless", "--scene", "kifs", "--out", "x.exr", "--preset-file", "a", "--preset-file", "b",
                     "--map", "a", "--map", "b"}),
            "accepted");
}

TEST(Flags, ListingsTakeAnOptionalScene) {
  const char* keys[] = {"vitrine", "--list-keys", "kifs"};
  const Options o = parseOptions(3, keys);
  EXPECT_EQ(o.mode, Mode::ListKeys);
  EXPECT_EQ(o.listParams, "kifs");
  const char* presets[] = {"vitrine", "--list-presets"};
  EXPECT_EQ(parseOptions(2, presets).mode, Mode::ListPresets);
  EXPECT_EQ(flagRefusal({"--list-presets", "nope"}),
            "Unknown scene 'nope'; the scenes are bloom, glass, neon, kifs, noodles, calibrate.");
  const char* alias[] = {"vitrine", "-h"};
  EXPECT_EQ(parseOptions(2, alias).mode, Mode::Help);
}

TEST(Flags, CompareTakesItsFlagsAndTwoImages) {
  const char* args[] = {"vitrine", "compare", "--fail-fraction", "0.25", "a.exr", "--hard-limit", "2", "b.exr"};
  const Options o = parseOptions(8, args);
  EXPECT_EQ(o.mode, Mode::Compare);
  EXPECT_EQ(o.compare, (std::vector<std::string>{"a.exr", "b.exr"}));
  EXPECT_DOUBLE_EQ(o.compareThresholds.failFraction, 0.25);
  EXPECT_FLOAT_EQ(o.compareThresholds.hardLimit, 2.0f);
  EXPECT_EQ(flagRefusal({"compare", "--fail-fraction", "2", "a.exr", "b.exr"}),
            "compare --fail-fraction takes a number from 0 to 1, not '2'.");
  EXPECT_EQ(flagRefusal({"compare", "a.exr"}), "compare expects two EXR files: REFERENCE CANDIDATE.");
  EXPECT_EQ(flagRefusal({"compare", "a.exr", "b.exr", "--fps", "3"}), "--fps is only for record runs, not compare.");
}

// ------------------------------------------------------------------------------------------ --help

std::vector<std::string> textLines(const std::string& text) {
  std::vector<std::string> list;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) list.push_back(line);
  return list;
}

TEST(FlagsHelp, NamesEveryFlagWithItsHelpWithinAHundredColumns) {
  const std::string text = help::usage();
  for (const std::string& line : textLines(text)) EXPECT_LE(line.size(), 100u) << line;
  for (const flags::Flag& flag : flags::table()) {
    std::string entry = flag.alias.empty() ? "\n  " : fmt::format("\n  {}, ", flag.alias);
    entry += flag.metavar.empty() ? std::string(flag.name) : fmt::format("{} {}", flag.name, flag.metavar);
    EXPECT_NE(text.find(entry), std::string::npos) << flag.name << " has no entry";
    // The help's first words follow the name, on its line or the next.
    const std::string start(flag.help.substr(0, flag.help.find(' ', 12)));
    EXPECT_NE(text.find(start), std::string::npos) << flag.name;
  }
  EXPECT_NE(text.find("  vitrine record --scene NAME --out FILE --seconds S [--isf FILE]... [--size WxH]"), std::string::npos) << text;
  std::string oneLine = text;  // the closing sentence, wherever it wraps
  for (char& c : oneLine) c = c == '\n' ? ' ' : c;
  EXPECT_NE(oneLine.find("except --isf, --set, --filter, --preset, --preset-file, --map and --remote-allow, which repeat."),
            std::string::npos);
}

TEST(FlagsHelp, TheManPageHasEveryFlagAndNoBareMinus) {
  const std::string page = help::manPage();
  EXPECT_EQ(page.rfind(".TH VITRINE 1", 0), 0u);
  for (const flags::Flag& flag : flags::table()) {
    auto roffName = [](std::string_view name) {
      std::string out;
      for (const char c : name) out += c == '-' ? std::string("\\-") : std::string(1, c);
      return out;
    };
    const std::string tag = flag.alias.empty()
                                ? ".TP\n\\fB" + roffName(flag.name) + "\\fR"
                                : ".TP\n\\fB" + roffName(flag.alias) + "\\fR, \\fB" + roffName(flag.name) + "\\fR";
    EXPECT_NE(page.find(tag), std::string::npos) << flag.name;
  }
  for (const std::string& line : textLines(page)) {
    EXPECT_FALSE(line.starts_with("'")) << line;
    for (size_t i = line.find('-'); i != std::string::npos; i = line.find('-', i + 1))
      EXPECT_TRUE(i > 0 && line[i - 1] == '\\') << "a hyphen roff would break: " << line;
  }
}

TEST(FlagsHelp, TheCompletionScriptOffersEveryFlagAndEveryChoice) {
  const std::string script = help::bashCompletion();
  for (const flags::Flag& flag : flags::table()) {
    bool named = false;  // as a whole word: in a list of flags or a case pattern
    for (const char after : {' ', '\'', '|', ')'}) named = named || script.find(std::string(flag.name) + after) != std::string::npos;
    EXPECT_TRUE(named) << flag.name;
    if (flag.value == flags::Value::Choice) {
      EXPECT_NE(script.find(fmt::format("{}) COMPREPLY", flag.name)), std::string::npos) << flag.name;
    }
  }
}

}  // namespace
}  // namespace vitrine
