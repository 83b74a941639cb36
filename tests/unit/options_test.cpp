// Every rule of the command line: what is accepted, and the sentence for what is not.
#include "app/options.h"
#include "core/error.h"
#include "scenes/scene.h"
#include "support/temp_folder.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace vitrine {

void PrintTo(const SceneSetting& s, std::ostream* os) {
  *os << "{" << s.scene << "|" << s.key << "|" << s.value << "}";
}

namespace {

Options parse(std::vector<const char*> args) {
  args.insert(args.begin(), "vitrine");
  return parseOptions(int(args.size()), args.data());
}

// The error message of parsing `args`, or "accepted".
std::string refusal(std::vector<const char*> args) {
  try {
    parse(std::move(args));
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

// -------------------------------------------------------------------------------------- flash guard

TEST(Options, FlashGuardIsOnInKioskModeAndWithReducedMotionUnlessTold) {
  EXPECT_FALSE(flashGuardOn(parse({})));
  EXPECT_TRUE(flashGuardOn(parse({"--kiosk"})));
  EXPECT_TRUE(flashGuardOn(parse({"--headless", "--scene", "kifs", "--out", "x.exr", "--reduced-motion"})));
  EXPECT_FALSE(flashGuardOn(parse({"--kiosk", "--flash-guard", "off"})));
  EXPECT_TRUE(flashGuardOn(parse({"record", "--scene", "kifs", "--seconds", "1", "--out", "f", "--flash-guard", "ON"})));
  EXPECT_EQ(refusal({"--flash-guard", "maybe"}), "--flash-guard is on or off, not 'maybe'.");
  EXPECT_EQ(refusal({"--flash-guard"}), "--flash-guard needs a value; see vitrine --help.");
}

// ------------------------------------------------------------------------------------------- numbers

TEST(OptionsNumbers, TimeMustBeFinite) {
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e400"})
    EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--time", bad, "--out", "x.exr"}),
              fmt::format("--time expects a finite number of seconds, not '{}'.", bad));
  EXPECT_EQ(refusal({"--time", "soon"}), "--time expects a finite number of seconds, not 'soon'.");
  EXPECT_DOUBLE_EQ(parse({"--headless", "--scene", "kifs", "--out", "x.exr", "--time", "-1.5"}).time, -1.5);
  EXPECT_DOUBLE_EQ(parse({"record", "--scene", "kifs", "--out", "f", "--seconds", "1", "--time", "1e3"}).time, 1000.0);
}

TEST(OptionsNumbers, WholeNumbersNameTheirRange) {
  EXPECT_EQ(refusal({"--frames", "4294967296"}),
            "--frames expects a whole number from 1 to 4294967295, not '4294967296'.");
  EXPECT_EQ(refusal({"--frames", "0"}), "--frames expects a whole number from 1 to 4294967295, not '0'.");
  EXPECT_EQ(refusal({"--frames", "-1"}), "--frames expects a whole number from 1 to 4294967295, not '-1'.");
  EXPECT_EQ(refusal({"--frames", "2.5"}), "--frames expects a whole number from 1 to 4294967295, not '2.5'.");
  EXPECT_EQ(refusal({"--seed", "-1"}), "--seed expects a whole number from 0 to 4294967295, not '-1'.");
  EXPECT_EQ(refusal({"--seed", "x"}), "--seed expects a whole number from 0 to 4294967295, not 'x'.");
  EXPECT_EQ(refusal({"bench", "--warmup", "-3", "--json", "b.json"}),
            "--warmup expects a whole number from 0 to 4294967295, not '-3'.");
  EXPECT_EQ(parse({"--seed", "4294967295"}).seed, 4294967295u);
  EXPECT_EQ(parse({"bench", "--json", "b.json", "--frames", "4294967295"}).frames, 4294967295u);
  EXPECT_EQ(parse({"bench", "--warmup", "0", "--json", "b.json"}).warmup, 0u);
  EXPECT_FALSE(parse({"bench", "--json", "b.json"}).pipelineStats);
  EXPECT_TRUE(parse({"bench", "--pipeline-stats", "--json", "b.json"}).pipelineStats);
}

TEST(OptionsNumbers, SizesAreWholeAndPositive) {
  EXPECT_NE(refusal({"--size", "12by4"}).find("--size expects WIDTHxHEIGHT such as 1920x1080, not '12by4'"),
            std::string::npos);
  EXPECT_NE(refusal({"--size", "0x10"}).find("from 1 to"), std::string::npos) << refusal({"--size", "0x10"});
  EXPECT_NE(refusal({"--size", "-5x10"}).find("from 1 to"), std::string::npos);
  EXPECT_NE(refusal({"--size", "5x99999999999"}).find("from 1 to"), std::string::npos);
  const auto o = parse({"--headless", "--scene", "kifs", "--size", "100000x10", "--out", "x.exr"});
  EXPECT_EQ(o.size->width, 100000u);  // headless: the device's limit decides, when it is known
}

TEST(OptionsNumbers, GalleryWindowSizeIsCheckedBeforeAnyWindowOpens) {
  EXPECT_EQ(refusal({"--size", "100000x10"}),
            "--size expects each side of the gallery window from 1 to 16384, not '100000x10'.");
  EXPECT_EQ(refusal({"--size", "10x16385"}),
            "--size expects each side of the gallery window from 1 to 16384, not '10x16385'.");
  EXPECT_EQ(parse({"--size", "16384x16384"}).size->width, 16384u);
}

// ------------------------------------------------------------------------------------------- values

TEST(OptionsValues, AnOptionIsNotTakenAsTheValueOfTheOneBefore) {
  EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", "--size", "32x18"}),
            "--out needs a value, but got the option --size.");
  EXPECT_EQ(refusal({"--scene", "--headless"}), "--scene needs a value, but got the option --headless.");
  EXPECT_EQ(refusal({"--seed"}), "--seed needs a value; see vitrine --help.");
  EXPECT_DOUBLE_EQ(parse({"bench", "--json", "b.json", "--time", "-2"}).time, -2.0);  // a negative number is a value
}

TEST(OptionsValues, HeadlessWritesExrOrPng) {
  for (const char* bad : {"x.jpg", "x.txt", "x", "x.exr.bak"})
    EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", bad}),
              fmt::format("--out writes .exr (linear half float) or .png (8-bit sRGB), not '{}'.", bad));
  for (const char* good : {"x.exr", "x.png", "dir/x.EXR", "x.PNG"})
    EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", good}), "accepted") << good;
  EXPECT_EQ(refusal({"bench", "--json", "timings.txt"}), "accepted");  // any name for the JSON
}

TEST(OptionsValues, TheFormatIsDecidedByTheNameInAnyCase) {
  for (const char* good : {"x.Png", "x.pNG", "x.Exr"})
    EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", good}), "accepted") << good;
}

// ------------------------------------------------------------------------------- modes and repeats

// A flag that does nothing in a mode was once taken and ignored: `--headless --fps 10` rendered at 60
// frames a second, `--headless --json x.exr` wrote x.exr. Each is refused, naming the mode.
TEST(OptionsModes, AFlagOutsideItsModeIsRefusedNamingTheMode) {
  auto headless = [](std::vector<const char*> extra) {
    std::vector<const char*> args{"--headless", "--scene", "kifs", "--out", "x.exr"};
    args.insert(args.end(), extra.begin(), extra.end());
    return refusal(args);
  };
  EXPECT_EQ(headless({"--fps", "10"}), "--fps is only for record runs, not --headless.");
  EXPECT_EQ(headless({"--spp", "4"}), "--spp is only for record runs, not --headless.");
  EXPECT_EQ(headless({"--range", "0:3"}), "--range is only for record runs, not --headless.");
  EXPECT_EQ(headless({"--seconds", "2"}), "--seconds is only for record runs, not --headless.");
  EXPECT_EQ(headless({"--format", "png"}), "--format is only for record runs, not --headless.");
  EXPECT_EQ(headless({"--warmup", "3"}), "--warmup is only for bench runs, not --headless.");
  EXPECT_EQ(headless({"--pipeline-stats"}), "--pipeline-stats is only for bench runs, not --headless.");
  EXPECT_EQ(headless({"--kiosk"}), "--kiosk is only for the gallery, not --headless.");
  EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--json", "x.exr"}), "--json is only for bench runs, not --headless.");
  EXPECT_EQ(refusal({"bench", "--scene", "kifs", "--out", "b.json"}),
            "--out is only for --headless, record and encode runs, not bench.");
  EXPECT_EQ(refusal({"record", "--scene", "kifs", "--seconds", "1", "--out", "f", "--frames", "3"}),
            "--frames is only for --headless and bench runs, not record.");
  EXPECT_EQ(refusal({"--frames", "3"}), "--frames is only for --headless and bench runs, not the gallery.");
  EXPECT_EQ(refusal({"bench", "--json", "b.json", "--remote"}), "--remote is only for the gallery and --headless runs, not bench.");
  EXPECT_EQ(refusal({"--list-params", "kifs", "--validate"}), "accepted");  // listings take what they need
  EXPECT_EQ(headless({"--audio-in-device", "default"}), "--audio-in-device is only for the gallery, not --headless.");
  EXPECT_EQ(refusal({"--midi-in", "a.mid"}), "--midi-in is only for --headless and record runs, not the gallery.");
  EXPECT_EQ(refusal({"bench", "--json", "b.json", "--map", "lfo.sine.2=fold"}),
            "--map is only for the gallery, --headless and record runs, not bench.");
}

TEST(OptionsModes, LiveInputFlags) {
  const Options o = parse({"--headless", "--scene", "kifs", "--out", "x.exr", "--map", "a.map", "--map",
                           "audio.bass=fold", "--audio-in", "song.wav", "--midi-in", "knob.mid"});
  EXPECT_EQ(o.maps, (std::vector<std::string>{"a.map", "audio.bass=fold"}));
  EXPECT_EQ(o.audioIn, "song.wav");
  EXPECT_EQ(o.midiIn, "knob.mid");
  EXPECT_EQ(refusal({"--audio-in", "song.wav", "--audio-in-device", "default"}),
            "--audio-in FILE and --audio-in-device both feed the audio sources: give one of them.");
}

TEST(OptionsModes, AFlagGivenTwiceIsRefusedUnlessRepeatable) {
  EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--scene", "neon", "--out", "x.exr"}),
            "--scene is given twice; only --isf, --set, --filter, --preset, --preset-file, --map and --remote-allow may be given more than once.");
  EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", "a.exr", "--out", "b.exr"}),
            "--out is given twice; only --isf, --set, --filter, --preset, --preset-file, --map and --remote-allow may be given more than once.");
  EXPECT_EQ(refusal({"--validate", "--validate"}),
            "--validate is given twice; only --isf, --set, --filter, --preset, --preset-file, --map and --remote-allow may be given more than once.");
  EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", "x.exr", "--set", "step=2", "--set", "step=3",
                     "--preset", "a", "--preset", "b"}),
            "accepted");
}

// ----------------------------------------------------------------------------------- --set, --preset

TEST(OptionsSettings, SetTakesKeyValueOrSceneKeyValue) {
  const auto o = parse({"--set", "step=3", "--set", "noodles.grid=32", "--set", "noodles.noise_scale=0.5",
                        "--set", "tier=", "--set", "kifs.drag_x=a=b"});
  const std::vector<SceneSetting> expected{{"", "step", "3"},
                                           {"noodles", "grid", "32"},
                                           {"noodles", "noise_scale", "0.5"},  // a '.' after '=' is the value's
                                           {"", "tier", ""},
                                           {"kifs", "drag_x", "a=b"}};
  EXPECT_EQ(o.parameters, expected);
}

TEST(OptionsSettings, MalformedSetsAreRefused) {
  for (const char* bad : {"novalue", "=3", ".grid=3", "noodles.=3", "noodles.a.b=3", "noodles."})
    EXPECT_EQ(refusal({"--set", bad}), fmt::format("--set expects KEY=VALUE or SCENE.KEY=VALUE, not '{}'.", bad));
  EXPECT_EQ(refusal({"--set", "nope.grid=32"}),
            "Unknown scene 'nope' in --set nope.grid=32; the scenes are bloom, glass, neon, kifs, noodles, calibrate.");
}

TEST(OptionsSettings, ParametersForKeepsTheScenesOwnAndTheUnqualifiedWhenAskedInOrder) {
  const auto o = parse({"bench", "--json", "b.json", "--set", "noodles.grid=32", "--set", "speed=2", "--set",
                        "kifs.step=4", "--set", "noodles.grid=16"});
  using Pairs = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(parametersFor(o, "noodles", true), (Pairs{{"grid", "32"}, {"speed", "2"}, {"grid", "16"}}));
  EXPECT_EQ(parametersFor(o, "kifs", true), (Pairs{{"speed", "2"}, {"step", "4"}}));
  EXPECT_EQ(parametersFor(o, "kifs", false), (Pairs{{"step", "4"}})) << "not --scene's: only its own";
  EXPECT_EQ(parametersFor(Options{}, "kifs", true), Pairs{});
}

TEST(OptionsSettings, PresetsAreRepeatableAndMayNameTheirScene) {
  const auto o = parse({"--preset", "calm", "--preset", "noodles.storm", "--set", "step=2", "--preset", "calm"});
  const std::vector<SceneSetting> expected{{"", "calm", ""}, {"noodles", "storm", ""}, {"", "calm", ""}};
  EXPECT_EQ(o.presets, expected);
  EXPECT_EQ(o.parameters.size(), 1u);
  for (const char* bad : {"calm=1", ".calm", "noodles.", "noodles.a.b", ""})
    EXPECT_EQ(refusal({"--preset", bad}), fmt::format("--preset expects NAME or SCENE.NAME, not '{}'.", bad));
  EXPECT_EQ(refusal({"--preset", "nope.calm"}),
            "Unknown scene 'nope' in --preset nope.calm; the scenes are bloom, glass, neon, kifs, noodles, calibrate.");
}

// The user's presets: files applied in every run mode, saved by headless runs, exported on their own;
// the kiosk's playlist.
TEST(OptionsSettings, PresetFilesSavingAndExporting) {
  const auto o = parse({"--headless", "--scene", "kifs", "--out", "x.exr", "--preset-file", "a.json", "--preset-file",
                        "b.json", "--save-preset", "evening look"});
  EXPECT_EQ(o.presetFiles, (std::vector<std::string>{"a.json", "b.json"}));
  EXPECT_EQ(o.savePreset, "evening look");
  EXPECT_EQ(refusal({"--save-preset", "x"}), "--save-preset is only for --headless runs, not the gallery.");
  const auto e = parse({"--export-preset", "kifs.evening look", "--out", "e.json"});
  EXPECT_EQ(e.mode, Mode::ExportPreset);
  EXPECT_EQ(e.exportPreset, (SceneSetting{"kifs", "evening look", ""}));
  EXPECT_EQ(e.out, "e.json");
  EXPECT_EQ(refusal({"--export-preset", "x"}), "--export-preset needs --out FILE.json, where the preset's file is written.");
}

TEST(OptionsGallery, APlaylistIsTheKiosks) {
  EXPECT_EQ(parse({"--kiosk", "--playlist", "p.txt"}).playlist, "p.txt");
  EXPECT_EQ(refusal({"--playlist", "p.txt"}), "--playlist is the kiosk's: give --kiosk too.");
  EXPECT_EQ(refusal({"--kiosk", "--playlist", "p.txt", "--dwell", "5"}),
            "--dwell and --playlist both say how long a scene shows: the playlist gives each line's dwell.");
  EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", "x.exr", "--playlist", "p.txt"}),
            "--playlist is only for the gallery, not --headless.");
}

// ------------------------------------------------------------------------------------- --list-params

TEST(OptionsListParams, ListsEveryOrOneScene) {
  auto o = parse({"--list-params"});
  EXPECT_EQ(o.mode, Mode::ListParams);
  EXPECT_EQ(o.listParams, "");
  o = parse({"--list-params", "noodles"});
  EXPECT_EQ(o.mode, Mode::ListParams);
  EXPECT_EQ(o.listParams, "noodles");
  o = parse({"--list-params", "--validate"});  // an option after it is not a scene
  EXPECT_EQ(o.listParams, "");
  EXPECT_TRUE(o.validation);
  EXPECT_EQ(refusal({"--list-params", "nope"}),
            "Unknown scene 'nope'; the scenes are bloom, glass, neon, kifs, noodles, calibrate.");
}

TEST(Options, AnUnknownSceneIsRefusedNamingTheScenesAndTheOneItBegins) {
  EXPECT_EQ(unknownScene("nood"), "Unknown scene 'nood' (did you mean noodles?); the scenes are bloom, glass, neon, kifs, noodles, calibrate.");
  EXPECT_EQ(unknownScene("n"), "Unknown scene 'n'; the scenes are bloom, glass, neon, kifs, noodles, calibrate.") << "neon and noodles both begin so";
  EXPECT_EQ(unknownScene("", " in --set .x=1"), "Unknown scene '' in --set .x=1; the scenes are bloom, glass, neon, kifs, noodles, calibrate.");
}

// --------------------------------------------------------------- --input, --events, --reset-settings

using OptionsFiles = test::TempFolderTest;

TEST(Options, RecordTakesAFilmsShape) {
  const auto o = parse({"record", "--scene", "neon", "--seconds", "2.5", "--fps", "24", "--spp", "4", "--range",
                        "10:20", "--format", "PNG", "--out", "film"});
  EXPECT_EQ(o.mode, Mode::Record);
  EXPECT_DOUBLE_EQ(o.seconds, 2.5);
  EXPECT_DOUBLE_EQ(o.fps, 24.0);
  EXPECT_EQ(o.spp, 4u);
  ASSERT_TRUE(o.range);
  EXPECT_EQ(o.range->first, 10u);
  EXPECT_EQ(o.range->second, 20u);
  EXPECT_EQ(o.format, "png");
  EXPECT_EQ(refusal({"record", "--scene", "neon", "--out", "film"}), "record needs --seconds S, the film's length.");
  EXPECT_EQ(refusal({"record", "--scene", "neon", "--seconds", "1"}),
            "record needs --out FOLDER for the numbered frames.");
  EXPECT_EQ(refusal({"record", "--scene", "neon", "--seconds", "1", "--out", "f", "--range", "7:3"}),
            "--range expects FIRST:END, frames FIRST up to but not including END, not '7:3'.");
  EXPECT_EQ(refusal({"record", "--scene", "neon", "--seconds", "1", "--out", "f", "--fps", "0"}),
            "--fps expects a number above 0 and at most 1000, not '0'.");
  EXPECT_EQ(refusal({"record", "--scene", "neon", "--seconds", "1", "--out", "f", "--format", "tiff"}),
            "--format writes exr or png, not 'tiff'.");
  EXPECT_EQ(refusal({"record", "--scene", "neon", "--seconds", "1", "--out", "f", "--spp", "300"}),
            "--spp takes 1 to 256 samples a frame.");
  // A name that is a sound's or another film's is not a folder of frames: refused, not recorded into.
  EXPECT_EQ(refusal({"record", "--scene", "neon", "--seconds", "1", "--out", "x.mp3"}),
            "record writes a film as .mp4, .mov or .mkv, or frames into a folder; 'x.mp3' names a .mp3 file, "
            "which this build does not write: name the folder without .mp3.");
  EXPECT_EQ(refusal({"record", "--scene", "neon", "--seconds", "1", "--out", "take.WEBM"}),
            "record writes a film as .mp4, .mov or .mkv, or frames into a folder; 'take.WEBM' names a .webm file, "
            "which this build does not write: name the folder without .WEBM.");
  EXPECT_EQ(parse({"record", "--scene", "neon", "--seconds", "1", "--out", "take.2"}).out, "take.2");
}

TEST_F(OptionsFiles, InputAndEventsBelongToHeadlessRuns) {
  const std::string events = (folder_ / "events.jsonl").string();
  const auto o = parse({"--headless", "--scene", "kifs", "--input", "moves.txt", "--events", events.c_str(),
                        "--out", "x.exr"});
  EXPECT_EQ(o.input, "moves.txt");
  EXPECT_EQ(o.events, events);
  EXPECT_EQ(refusal({"--input", "moves.txt"}), "--input is only for --headless and record runs, not the gallery.");
  EXPECT_EQ(refusal({"--events", events.c_str()}), "--events is only for --headless and record runs, not the gallery.");
  EXPECT_EQ(refusal({"bench", "--json", "b.json", "--events", events.c_str()}),
            "--events is only for --headless and record runs, not bench.");
  EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", "x.exr", "--input"}),
            "--input needs a value; see vitrine --help.");
}

TEST_F(OptionsFiles, EventsMustBeWritable) {
  const std::string missing = (folder_ / "no-such-folder" / "events.jsonl").string();
  EXPECT_NE(refusal({"--headless", "--scene", "kifs", "--events", missing.c_str(), "--out", "x.exr"})
                .find("Cannot write " + missing + ": the folder"),
            std::string::npos);
  EXPECT_NE(refusal({"--headless", "--scene", "kifs", "--events", "/dev/full", "--out", "x.exr"})
                .find("not a regular file"),
            std::string::npos);
  const std::string anyName = (folder_ / "events.log").string();  // any name will do
  EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--events", anyName.c_str(), "--out", "x.exr"}), "accepted");
}

TEST(Options, HeadlessCommandLine) {
  const auto o = parse({"--headless", "--scene", "kifs", "--size", "320x180", "--frames", "4", "--time", "2.5",
                        "--seed", "9", "--set", "step=3", "--out", "x.exr"});
  EXPECT_EQ(o.mode, Mode::Headless);
  EXPECT_EQ(o.size->width, 320u);
  EXPECT_EQ(o.size->height, 180u);
  EXPECT_EQ(o.frames, 4u);
  EXPECT_DOUBLE_EQ(o.time, 2.5);
  EXPECT_EQ(o.seed, 9u);
  ASSERT_EQ(o.parameters.size(), 1u);
  EXPECT_EQ(o.parameters[0].value, "3");
}

TEST(Options, BadInputIsAnError) {
  EXPECT_THROW(parse({"--bogus"}), Error);
  EXPECT_THROW(parse({"--size", "12by4"}), Error);
  EXPECT_THROW(parse({"--size", "0x10"}), Error);
  EXPECT_THROW(parse({"--frames", "-1"}), Error);
  EXPECT_THROW(parse({"--headless", "--scene", "kifs"}), Error);  // no --out
  EXPECT_THROW(parse({"--set", "novalue"}), Error);
  EXPECT_THROW(parse({"--seed"}), Error);
}

// An empty name would save nothing and say nothing: it is refused with the flag's name.
TEST(Options, AnEmptyPresetNameIsRefused) {
  try {
    parse({"--headless", "--scene", "kifs", "--out", "x.exr", "--save-preset", ""});
    ADD_FAILURE() << "--save-preset \"\" accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--save-preset expects a name"), std::string::npos) << e.what();
  }
}

TEST(OptionsGallery, ResetSettings) {
  EXPECT_FALSE(parse({}).resetSettings);
  EXPECT_TRUE(parse({"--reset-settings"}).resetSettings);
}

}  // namespace
}  // namespace vitrine

namespace vitrine {
namespace {

TEST(OptionsAudio, AudioOutIsAHeadlessWavFile) {
  const char* ok[] = {"vitrine", "--headless", "--scene", "bloom", "--out", "/tmp/a.exr", "--audio-out", "/tmp/a.wav"};
  EXPECT_EQ(parseOptions(8, ok).audioOut, "/tmp/a.wav");
  const char* notWav[] = {"vitrine", "--headless", "--scene", "bloom", "--out", "/tmp/a.exr", "--audio-out", "/tmp/a.mp3"};
  EXPECT_THROW(parseOptions(8, notWav), Error);
  const char* gallery[] = {"vitrine", "--audio-out", "/tmp/a.wav"};
  EXPECT_THROW(parseOptions(3, gallery), Error);
}


// ------------------------------------------------------------------------------ filters, transitions

TEST(OptionsFilters, FilterSettingsAreTheirOwnAndInOrder) {
  const Options o = parse({"--headless", "--scene", "kifs", "--out", "x.exr", "--filter", "a/invert.fs", "--filter",
                           "b/gain.fs", "--set", "filter.invert.amount=0.5", "--set", "step=3", "--set",
                           "filter.gain.gain=2"});
  EXPECT_EQ(o.filters, (std::vector<std::string>{"a/invert.fs", "b/gain.fs"}));
  EXPECT_EQ(o.filterParameters,
            (std::vector<FilterSetting>{{"invert", "amount", "0.5"}, {"gain", "gain", "2"}}));
  ASSERT_EQ(o.parameters.size(), 1u);
  EXPECT_EQ(o.parameters[0].key, "step");
}

TEST(OptionsFilters, MalformedFilterAndTransitionSettingsSayTheirForm) {
  for (const char* bad : {"filter.invert=1", "filter..amount=1", "filter.invert.=1", "filter.a.b.c=1", "filter.a.b"})
    EXPECT_NE(refusal({"--headless", "--scene", "kifs", "--out", "x.exr", "--set", bad}).find("filter.NAME.KEY=VALUE"),
              std::string::npos)
        << bad;
  EXPECT_NE(refusal({"--set", "transition.a.b=1", "--transition", "t.fs"}).find("transition.KEY=VALUE"), std::string::npos);
  EXPECT_NE(refusal({"--set", "transition.dip=1"}).find("needs --transition FILE"), std::string::npos);
  EXPECT_EQ(parse({"--transition", "t.fs", "--set", "transition.dip=1"}).transitionParameters,
            (std::vector<std::pair<std::string, std::string>>{{"dip", "1"}}));
  EXPECT_NE(refusal({"--headless", "--scene", "kifs", "--out", "x.exr", "--transition", "t.fs"}).find("--transition"),
            std::string::npos);
}

}  // namespace
}  // namespace vitrine
