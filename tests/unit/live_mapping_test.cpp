// Mappings (live/mapping.h) and the modulator (live/modulator.h): the text, the checks against a
// scene, and a step's range, curve, smoothing and soft takeover.
#include "core/error.h"
#include "host/live_link.h"
#include "live/mapping.h"
#include "live/modulator.h"
#include "live/source_bank.h"
#include "params/settings_file.h"
#include "scenes/scene.h"
#include "scenes/glass/settings.h"
#include "scenes/kifs/settings.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace vitrine::live {
namespace {

const SceneInfo& scene(std::string_view name) { return *findScene(name); }

Mapping parsed(std::string_view text) {
  std::string why;
  auto mapping = parseMapping(text, &why);
  EXPECT_TRUE(mapping) << text << ": " << why;
  return mapping.value_or(Mapping{});
}

std::string refusal(std::string_view text) {
  std::string why;
  EXPECT_FALSE(parseMapping(text, &why)) << text;
  return why;
}

TEST(LiveMapping, ParsesEveryPart) {
  const Mapping m = parsed("midi.cc.1.21=glass.abbe:60:4 curve=log attack=0.01 release=0.25 takeover=jump");
  EXPECT_EQ(m.source, "midi.cc.1.21");
  EXPECT_EQ(m.scene, "glass");
  EXPECT_EQ(m.target, "abbe");
  EXPECT_EQ(m.lo, "60");
  EXPECT_EQ(m.hi, "4");
  EXPECT_EQ(m.curve, Curve::Log);
  EXPECT_FLOAT_EQ(m.attack, 0.01f);
  EXPECT_FLOAT_EQ(m.release, 0.25f);
  EXPECT_EQ(m.takeoverMode(), Takeover::Jump);
  EXPECT_EQ(parsed("midi.cc.1.21=abbe").takeoverMode(), Takeover::Soft);  // a knob: soft by default
  EXPECT_EQ(parsed("audio.bass=abbe").takeoverMode(), Takeover::Jump);
  EXPECT_EQ(parsed("audio.beat=neon.release args=0,6,4").args, (std::vector<float>{0, 6, 4}));
}

TEST(LiveMapping, FormatRoundTrips) {
  for (const char* text : {"audio.bass=kifs.fold:1:1.14 attack=0.015 release=0.35", "audio.beat=neon.burst",
                           "midi.note.10.36=glass.shape:pill:plate takeover=soft", "lfo.sine.0.5=exposure curve=smooth",
                           "pad.0.axis.1=noodles.speed:0:3 curve=ease-in", "osc.fader=bloom.breath",
                           "audio.onset=neon.release args=-3,8,2.5"}) {
    const Mapping m = parsed(text);
    EXPECT_EQ(formatMapping(m), text);
    EXPECT_EQ(parsed(formatMapping(m)), m);
  }
}

TEST(LiveMapping, RefusesMalformedText) {
  EXPECT_NE(refusal("").find("empty"), std::string::npos);
  EXPECT_NE(refusal("audio.bass").find("no '='"), std::string::npos);
  EXPECT_NE(refusal("audio.treble=kifs.fold").find("audio sources are"), std::string::npos);
  EXPECT_NE(refusal("midi.cc.17.1=kifs.fold").find("channel 1..16"), std::string::npos);
  EXPECT_NE(refusal("midi.cc.1.128=kifs.fold").find("number 0..127"), std::string::npos);
  EXPECT_NE(refusal("pad.0.axis.9=kifs.fold").find("pad.N.axis.K"), std::string::npos);
  EXPECT_NE(refusal("lfo.wobble.2=kifs.fold").find("lfo.sine"), std::string::npos);
  EXPECT_NE(refusal("lfo.sine.0=kifs.fold").find("PERIOD"), std::string::npos);
  EXPECT_NE(refusal("osc.a/b=kifs.fold").find("osc.NAME"), std::string::npos);
  EXPECT_NE(refusal("keyboard.a=kifs.fold").find("sources are"), std::string::npos);
  EXPECT_NE(refusal("audio.bass=kifs.fold:1").find("two values"), std::string::npos);
  EXPECT_NE(refusal("audio.bass=kifs.fold::1").find("both ends"), std::string::npos);
  EXPECT_NE(refusal("audio.bass=a.b.c").find("not a target"), std::string::npos);
  EXPECT_NE(refusal("audio.bass=kifs.fold curve=cubic").find("curve=cubic"), std::string::npos);
  EXPECT_NE(refusal("audio.bass=kifs.fold attack=-1").find("seconds"), std::string::npos);
  EXPECT_NE(refusal("audio.bass=kifs.fold wobble=1").find("unknown option"), std::string::npos);
  EXPECT_NE(refusal("audio.bass=kifs.fold release").find("options are"), std::string::npos);
}

TEST(LiveMapping, ChecksTargetsAgainstTheScene) {
  EXPECT_EQ(checkMapping(parsed("audio.bass=fold:1:1.2"), scene("kifs")), "");
  EXPECT_EQ(checkMapping(parsed("audio.beat=burst"), scene("neon")), "");
  EXPECT_NE(checkMapping(parsed("audio.bass=nope"), scene("kifs")).find("names no parameter or action"), std::string::npos);
  EXPECT_NE(checkMapping(parsed("audio.bass=lattice"), scene("bloom")).find("rebuilds"), std::string::npos);
  EXPECT_NE(checkMapping(parsed("audio.bass=colour_a"), scene("neon")).find("colour"), std::string::npos);
  EXPECT_NE(checkMapping(parsed("audio.bass=grid"), scene("noodles")).find("rebuilds"), std::string::npos);
  // Out-of-range ends are refused with the parameter's own reason.
  EXPECT_NE(checkMapping(parsed("audio.bass=fold:0:1"), scene("kifs")).find("from 0.8 to 1.3"), std::string::npos);
  EXPECT_NE(checkMapping(parsed("audio.bass=shape:pill:sphere"), scene("glass")).find("sphere"), std::string::npos);
  EXPECT_NE(checkMapping(parsed("audio.bass=jitter:0:1"), scene("glass")).find("switch"), std::string::npos);
  EXPECT_NE(checkMapping(parsed("audio.beat=release"), scene("neon")).find("args="), std::string::npos);
  EXPECT_EQ(checkMapping(parsed("audio.beat=release args=0,6,4"), scene("neon")), "");
  EXPECT_NE(checkMapping(parsed("audio.beat=burst:0:1"), scene("neon")).find("action"), std::string::npos);
  EXPECT_NE(checkMapping(parsed("audio.bass=kifs.fold"), scene("glass")).find("for kifs"), std::string::npos);
}

// The scenes' own audio mappings: every one parses and fits its scene.
TEST(LiveMapping, EverySceneAudioMappingFits) {
  size_t count = 0;
  for (const SceneInfo& info : sceneRegistry())
    for (const std::string& line : info.schema().audioMappings()) {
      const Mapping m = parsed(line);
      EXPECT_TRUE(m.source.starts_with("audio.")) << line;
      EXPECT_EQ(checkMapping(m, info), "") << info.name << ": " << line;
      ++count;
    }
  EXPECT_GE(count, sceneRegistry().size());  // each scene plays with the music
}

// A file of exactly the most lines allowed, ending as text files do (a final newline, an editor's
// UTF-8 byte-order mark), is accepted; one line more is refused on the line past the limit.
TEST(LiveMapping, FileOfTheMostLinesWithAFinalNewlineAndAByteOrderMark) {
  const auto dir = std::filesystem::temp_directory_path() / "vitrine-live-mapping-lines";
  std::filesystem::create_directories(dir);
  std::string text = "\xEF\xBB\xBF" "audio.bass=kifs.fold:1:1.1\n";
  for (int line = 2; line <= 4096; ++line) text += "# a comment\n";
  std::ofstream(dir / "full.map", std::ios::binary) << text;
  EXPECT_NO_THROW({ EXPECT_EQ(loadMappingFile(dir / "full.map").size(), 1u); });
  std::ofstream(dir / "over.map", std::ios::binary) << text << "# one more\n";
  try {
    loadMappingFile(dir / "over.map");
    ADD_FAILURE() << "4,097 lines accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("over.map:4097: a mapping file has at most 4096 lines"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(LiveMapping, FileRoundTripsAndNamesTheBadLine) {
  const auto dir = std::filesystem::temp_directory_path() / "vitrine-live-mapping-test";
  std::filesystem::create_directories(dir);
  const std::vector<Mapping> mappings{parsed("audio.bass=kifs.fold:1:1.14 release=0.3"),
                                      parsed("midi.cc.1.21=glass.abbe:60:4 curve=log"), parsed("audio.beat=neon.burst")};
  saveMappingFile(dir / "set.map", mappings);
  EXPECT_EQ(loadMappingFile(dir / "set.map"), mappings);

  const auto expectRefused = [&](const std::string& text, const std::string& where, const std::string& what) {
    std::ofstream(dir / "bad.map") << text;
    try {
      loadMappingFile(dir / "bad.map");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find((dir / "bad.map").string() + ":" + where + ":"), std::string::npos) << message;
      EXPECT_NE(message.find(what), std::string::npos) << message;
    }
  };
  expectRefused("# comment\n\naudio.bass=kifs.fold:1:1.1\naudio.bass=kifs.fold:0:9\n", "4", "from 0.8 to 1.3");
  expectRefused("audio.bass=fold\n", "1", "names the scene");
  expectRefused("audio.bass=moon.fold\n", "1", "Unknown scene 'moon'; the scenes are bloom");
  expectRefused("audio.bass=bloom.lattice:64:96\n", "1", "rebuilds");
  expectRefused("audio.bass=kifs.fold \x01\n", "1", "plain ASCII");
  EXPECT_THROW(loadMappingFile(dir / "missing.map"), Error);
  std::filesystem::remove_all(dir);
}

TEST(LiveMapping, Lfos) {
  EXPECT_NEAR(lfoValue("lfo.sine.4", 0.0), 0.0f, 1e-6f);
  EXPECT_NEAR(lfoValue("lfo.sine.4", 2.0), 1.0f, 1e-6f);
  EXPECT_NEAR(lfoValue("lfo.triangle.2", 0.5), 0.5f, 1e-6f);
  EXPECT_NEAR(lfoValue("lfo.saw.0.5", 0.375), 0.75f, 1e-6f);
  EXPECT_EQ(lfoValue("lfo.square.1", 0.25), 1.0f);
  EXPECT_EQ(lfoValue("lfo.square.1", 0.75), 0.0f);
  SourceBank bank;
  bank.setTime(1.0);
  EXPECT_NEAR(bank.value("lfo.sine.2"), 1.0f, 1e-6f);
  bank.set("audio.bass", 3.0f);
  EXPECT_EQ(bank.value("audio.bass"), 1.0f);  // clamped
  EXPECT_EQ(bank.value("midi.cc.1.1"), 0.0f);  // never moved
}

TEST(LiveMapping, SmoothingAndCurves) {
  EXPECT_EQ(smooth(0.0f, 1.0f, 1.0f / 60.0f, 0.0f, 0.5f), 1.0f);  // no attack: at once
  const float rising = smooth(0.0f, 1.0f, 0.1f, 0.1f, 0.0f);
  EXPECT_NEAR(rising, 1.0f - std::exp(-1.0f), 1e-6f);  // one time constant: 63 %
  EXPECT_NEAR(smooth(1.0f, 0.0f, 0.5f, 0.0f, 0.5f), std::exp(-1.0f), 1e-6f);
  EXPECT_EQ(applyCurve(Curve::EaseIn, 0.5f), 0.25f);
  EXPECT_EQ(applyCurve(Curve::EaseOut, 0.5f), 0.75f);
  EXPECT_EQ(applyCurve(Curve::Smooth, 0.5f), 0.5f);
  EXPECT_EQ(applyCurve(Curve::Smooth, 0.25f), 0.15625f);
  EXPECT_EQ(applyCurve(Curve::Linear, 2.0f), 1.0f);
}

struct KifsRig {
  kifs::Settings settings;
  params::Bound bound = params::bindSettings(kifs::schema(), settings);
  Modulator modulator;
  SourceBank bank;
  void step(float dt = 1.0f / 60.0f) { EXPECT_EQ(params::applyValues(bound, modulator.step(bank, bound, dt).values), ""); }
  std::string fold() const { return params::formatFloat(settings.fold); }
};

TEST(LiveModulator, RangeAndCurveReachTheParameter) {
  KifsRig rig;
  rig.modulator.setMappings(scene("kifs"), {parsed("audio.bass=kifs.fold:1:1.2")});
  rig.bank.set("audio.bass", 0.5f);
  rig.step();
  EXPECT_EQ(rig.fold(), "1.1");
  rig.modulator.setMappings(scene("kifs"), {parsed("audio.bass=kifs.fold:1.2:1 curve=ease-in")});  // backwards
  rig.step();
  EXPECT_EQ(rig.fold(), "1.15");
  rig.modulator.setMappings(scene("kifs"), {parsed("audio.bass=kifs.fold:0.8:1.25 curve=log")});
  rig.bank.set("audio.bass", 1.0f);
  rig.step();
  EXPECT_EQ(rig.fold(), "1.25");
  rig.modulator.setMappings(scene("kifs"), {parsed("audio.bass=kifs.step")});  // int over its whole range 1..9
  rig.bank.set("audio.bass", 0.5f);
  rig.step();
  EXPECT_EQ(rig.settings.step, 5);
}

TEST(LiveModulator, SmoothingFollowsAttackAndRelease) {
  KifsRig rig;
  rig.modulator.setMappings(scene("kifs"), {parsed("audio.bass=kifs.fold:1:1.2 attack=0.1 release=1")});
  rig.step();  // the first step starts where the source is: 0
  EXPECT_EQ(rig.fold(), "1");
  rig.bank.set("audio.bass", 1.0f);
  rig.step(0.1f);  // one attack time constant: 63 % of the way
  EXPECT_NEAR(rig.settings.fold, 1.0f + 0.2f * (1.0f - std::exp(-1.0f)), 1e-5f);
  for (int i = 0; i < 20; ++i) rig.step(0.1f);
  EXPECT_NEAR(rig.settings.fold, 1.2f, 1e-5f);
  rig.bank.set("audio.bass", 0.0f);
  rig.step(0.1f);  // the release is ten times slower
  EXPECT_NEAR(rig.settings.fold, 1.2f - 0.2f * (1.0f - std::exp(-0.1f)), 1e-5f);
}

TEST(LiveModulator, SoftTakeoverWaitsForTheControl) {
  KifsRig rig;
  rig.settings.fold = 1.2f;  // set by hand
  rig.modulator.setMappings(scene("kifs"), {parsed("midi.cc.1.1=kifs.fold:1:1.3")});
  rig.bank.set("midi.cc.1.1", 0.0f);  // the knob is far below
  rig.step();
  EXPECT_EQ(rig.fold(), "1.2");
  EXPECT_FALSE(rig.modulator.states()[0].engaged);
  rig.bank.set("midi.cc.1.1", 0.3f);  // 1.09: still below
  rig.step();
  EXPECT_EQ(rig.fold(), "1.2");
  rig.bank.set("midi.cc.1.1", 0.8f);  // 1.24: it passed the value, so it takes over
  rig.step();
  EXPECT_EQ(rig.fold(), "1.24");
  EXPECT_TRUE(rig.modulator.states()[0].engaged);
  rig.settings.fold = 0.9f;  // the panel moves it: the knob lets go until it meets it again
  rig.bank.set("midi.cc.1.1", 0.7f);
  rig.step();
  EXPECT_EQ(rig.fold(), "0.9");
  // A jump mapping writes at once.
  rig.modulator.setMappings(scene("kifs"), {parsed("midi.cc.1.1=kifs.fold:1:1.3 takeover=jump")});
  rig.step();
  EXPECT_EQ(rig.fold(), "1.21");
}

TEST(LiveModulator, ActionsFireOnRisingEdges) {
  Modulator modulator;
  modulator.setMappings(scene("neon"), {parsed("audio.beat=neon.burst"), parsed("audio.onset=neon.release args=0,6,4")});
  auto defaults = scene("neon").schema().makeDefaults();
  const params::Bound bound{&scene("neon").schema(), defaults.get()};
  SourceBank bank;
  std::vector<size_t> fired;
  const float beats[] = {0, 1, 1, 0, 1, 0, 0};
  for (float beat : beats) {
    bank.set("audio.beat", beat);
    bank.set("audio.onset", beat);
    fired.push_back(modulator.step(bank, bound, 1.0f / 60.0f).actions.size());
  }
  EXPECT_EQ(fired, (std::vector<size_t>{0, 2, 0, 0, 2, 0, 0}));
  bank.set("audio.beat", 1.0f);
  const Modulated out = modulator.step(bank, bound, 1.0f / 60.0f);
  ASSERT_EQ(out.actions.size(), 1u);
  EXPECT_EQ(out.actions[0], (ActionCall{"burst", {}}));
}

TEST(LiveModulator, ChoicesAndSwitches) {
  glass::Settings settings;
  const params::Bound bound = params::bindSettings(glass::schema(), settings);
  Modulator modulator;
  modulator.setMappings(scene("glass"), {parsed("pad.0.axis.0=glass.shape:pill:plate takeover=jump"), parsed("pad.0.button.0=glass.jitter")});
  SourceBank bank;
  const auto at = [&](float x, float button) {
    bank.set("pad.0.axis.0", x);
    bank.set("pad.0.button.0", button);
    EXPECT_EQ(params::applyValues(bound, modulator.step(bank, bound, 0.016f).values), "");
    return glass::schema().find("shape")->format(&settings) + " " + glass::schema().find("jitter")->format(&settings);
  };
  EXPECT_EQ(at(0.0f, 0.0f), "pill off");
  EXPECT_EQ(at(0.3f, 1.0f), "prism on");
  EXPECT_EQ(at(0.6f, 1.0f), "cube on");
  EXPECT_EQ(at(1.0f, 0.0f), "plate off");
}

TEST(LiveSettings, MappingsAndAudioInputRoundTripThroughTheSettingsFile) {
  const auto dir = std::filesystem::temp_directory_path() / "vitrine-live-settings-test";
  std::filesystem::remove_all(dir);
  const auto path = dir / "settings.json";
  const params::SchemaLookup lookup = [](std::string_view name) -> const params::Schema* {
    const SceneInfo* info = findScene(name);
    return info ? &info->schema() : nullptr;
  };
  params::Settings settings;
  settings.mappings["kifs"] = {"midi.cc.1.21=kifs.fold:0.9:1.2"};
  settings.audioInput = true;
  settings.audioDevice = "2";
  params::saveSettings(path, settings, lookup);
  const params::LoadResult loaded = params::loadSettings(path, lookup);
  EXPECT_TRUE(loaded.warnings.empty());
  EXPECT_EQ(loaded.settings.mappings, settings.mappings);
  EXPECT_TRUE(loaded.settings.audioInput);
  EXPECT_EQ(loaded.settings.audioDevice, "2");
  // Another gallery's mappings for another scene survive a merge that changed only kifs'.
  params::Settings disk = loaded.settings;
  disk.mappings["glass"] = {"audio.high=glass.abbe:12:2"};
  params::Settings ours;
  ours.mappings["kifs"] = {"audio.bass=kifs.fold:1:1.1"};
  params::SettingsChanges changed;
  changed.mappings.insert("kifs");
  const params::Settings merged = params::mergeSettings(disk, ours, changed);
  EXPECT_EQ(merged.mappings.at("kifs"), ours.mappings.at("kifs"));
  EXPECT_EQ(merged.mappings.at("glass"), disk.mappings.at("glass"));
  EXPECT_TRUE(merged.audioInput);  // not changed here
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vitrine::live

namespace vitrine::host {
namespace {

// MIDI learn's half in LiveLink: the control that moved most since it was last asked, MIDI or gamepad;
// a stick at rest, a control that did not move, and audio are not candidates.
TEST(LiveLearn, TheControlThatMovedMostIsLearnt) {
  LiveLink link(LiveConfig{});
  link.readInputs(0.0);
  EXPECT_FALSE(link.takeMovedControl());
  link.sources().set("pad.0.axis.0", 0.5f);  // at rest
  link.sources().set("audio.bass", 1.0f);    // not a control
  link.readInputs(0.1);
  EXPECT_FALSE(link.takeMovedControl());
  link.sources().set("midi.cc.1.7", 0.2f);
  link.sources().set("pad.0.axis.0", 0.9f);
  link.readInputs(0.2);
  EXPECT_EQ(link.takeMovedControl(), "pad.0.axis.0");
  EXPECT_FALSE(link.takeMovedControl());  // once
  link.sources().set("midi.cc.1.7", 0.25f);
  link.readInputs(0.3);
  EXPECT_EQ(link.takeMovedControl(), "midi.cc.1.7");
}

// --map lines are checked against their scene when the run starts; an unqualified one is the run's scene's.
TEST(LiveLearn, CommandLineMappingsAreCheckedAtStart) {
  LiveLink link(LiveConfig{.maps = {"audio.bass=fold:1:1.1"}, .runScene = "kifs"});
  ASSERT_EQ(link.commandLineMappings().size(), 1u);
  EXPECT_EQ(link.commandLineMappings()[0].scene, "kifs");
  EXPECT_THROW(LiveLink(LiveConfig{.maps = {"audio.bass=lattice"}, .runScene = "bloom"}), Error);
  EXPECT_THROW(LiveLink(LiveConfig{.maps = {"/nonexistent/file.map"}, .runScene = "kifs"}), Error);
  EXPECT_THROW(LiveLink(LiveConfig{.audioFile = "/nonexistent/song.wav"}), Error);
}

}  // namespace
}  // namespace vitrine::host
