// The lights' pure parts (src/lights/): the patch and its refusals, fixtures packed into universes, 16-bit
// pairs and the dmx.* sources, the frame's regions and dominant colours, and the flash limit on lights.
#include "core/error.h"
#include "host/flash_guard_math.h"
#include "host/live_link.h"
#include "lights/dmx_sources.h"
#include "lights/fixtures.h"
#include "lights/frame_colours.h"
#include "lights/light_guard.h"
#include "lights/patch.h"
#include "live/mapping.h"
#include "live/modulator.h"
#include "live/source_bank.h"
#include "scenes/catalogue.h"
#include "scenes/kifs/settings.h"

#include <gtest/gtest.h>

#include <string>

namespace vitrine::lights {
namespace {

std::string refusal(const std::string& text) {
  try {
    parsePatch(text, "room.json");
  } catch (const Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << text;
  return {};
}

TEST(LightsPatch, ReadsEveryPart) {
  const Patch patch = parsePatch(R"({
  "grid": [8, 2], "master": 0.5, "input": [1, 2, 1], "olad": 9100,
  "master_source": "dmx.1.512", "blackout_source": "osc.blackout",
  "fixtures": [
    {"name": "wall", "type": "pixels", "count": 16, "universe": 0, "address": 1, "signal": "regions"},
    {"type": "rgbw", "universe": 0, "address": 49, "signal": "dominant", "index": 1},
    {"type": "dimmer", "universe": 3, "address": 512, "signal": "bloom.chamber"}
  ]})", "room.json");
  EXPECT_EQ(patch.gridWidth, 8);
  EXPECT_EQ(patch.gridHeight, 2);
  EXPECT_FLOAT_EQ(patch.master, 0.5f);
  EXPECT_EQ(patch.input, (std::vector<uint32_t>{1, 2}));
  EXPECT_EQ(patch.oladPort, 9100);
  EXPECT_EQ(patch.masterSource, "dmx.1.512");
  EXPECT_EQ(patch.blackoutSource, "osc.blackout");
  ASSERT_EQ(patch.fixtures.size(), 3u);
  EXPECT_EQ(patch.fixtures[0].name, "wall");
  EXPECT_EQ(channels(patch.fixtures[0]), 48);
  EXPECT_EQ(patch.fixtures[1].name, "fixture 2");
  EXPECT_EQ(patch.fixtures[1].index, 1);
  EXPECT_EQ(patch.fixtures[1].line, 6);
  EXPECT_EQ(channels(patch.fixtures[2]), 1);
}

TEST(LightsPatch, RefusesHostilePatchesNamingTheLine) {
  EXPECT_EQ(refusal("{\n  \"fixtures\": [\n    {\"type\": \"rgb\",,}\n  ]\n}"), "room.json:3: not JSON: syntax error while parsing object key - unexpected ','; expected string literal");
  EXPECT_EQ(refusal("{\n\"fixtures\": [\n{\"type\": \"laser\", \"universe\": 0, \"address\": 1, \"signal\": \"regions\"}]}"),
            "room.json:3: unknown fixture type \"laser\" (known: rgb, rgbw, dimmer, pixels)");
  EXPECT_EQ(refusal("{\"fixtures\": [\n{\"type\": \"rgb\", \"universe\": 0,\n \"address\": 0, \"signal\": \"regions\"}]}"),
            "room.json:3: address 0 is outside 1..512");
  EXPECT_EQ(refusal("{\"fixtures\": [\n{\"type\": \"rgb\", \"universe\": 0, \"address\": 511, \"signal\": \"regions\"}]}"),
            "room.json:2: fixture 1 takes channels 511..513 of universe 0: past 512");
  EXPECT_EQ(refusal("{\"fixtures\": [\n{\"type\": \"pixels\", \"count\": 100000, \"universe\": 0, \"address\": 1, \"signal\": \"regions\"}]}"),
            "room.json:2: a strip's pixel count 100000 is outside 1..170");
  EXPECT_EQ(refusal("{\"fixtures\": [\n{\"name\": \"a\", \"type\": \"rgb\", \"universe\": 4, \"address\": 10, \"signal\": \"regions\"},\n"
                    "{\"name\": \"b\", \"type\": \"rgbw\", \"universe\": 4, \"address\": 8, \"signal\": \"regions\"}]}"),
            "room.json:3: b (channels 8..11 of universe 4) overlaps a (channels 10..12, line 2)");
  EXPECT_EQ(refusal("{\"fixtures\": [{\"type\": \"rgb\", \"universe\": 0, \"address\": 1, \"signal\": \"sun\"}]}"),
            "room.json:1: unknown signal \"sun\" (known: regions, dominant, bloom.phase, bloom.chamber, bloom.climax, neon.tubes, neon.glow)");
  EXPECT_EQ(refusal("{\"grid\": [8, 1],\n \"fixturs\": []}"), "room.json:2: unknown key 'fixturs' (known: grid, master, master_source, blackout_source, input, olad, fixtures)");
  EXPECT_EQ(refusal("{\"universe\": -1}"),
            "room.json:1: unknown key 'universe' (known: grid, master, master_source, blackout_source, input, olad, fixtures)");
  EXPECT_EQ(refusal("{\"master_source\": \"dmx.1.600\"}"),
            "room.json:1: \"master_source\" is a live source (docs/LIVE.md): 'dmx.1.600' is not a source: DMX sources are "
            "dmx.UNIVERSE.CHANNEL (channel 1..512) and dmx16.UNIVERSE.CHANNEL (the 16-bit pair of CHANNEL and the next, "
            "1..511), universe 0..65535");
  EXPECT_EQ(refusal("{\"input\": [70000]}"), "room.json:1: universe 70000 is outside 0..65535");
  EXPECT_EQ(refusal("{\"grid\": [1000, 1]}"), "room.json:1: the grid's width 1000 is outside 1..64");
  EXPECT_EQ(refusal("[1, 2]"), "room.json:1: a patch is an object {\"fixtures\": [...], ...}");
  std::string many = "{\"fixtures\": [";
  for (size_t i = 0; i <= kMaxFixtures; ++i)
    many += (i ? "," : "") + std::string("{\"type\": \"dimmer\", \"universe\": ") + std::to_string(i / 512) +
            ", \"address\": " + std::to_string(i % 512 + 1) + ", \"signal\": \"regions\"}";
  EXPECT_EQ(refusal(many + "]}"), "room.json:1: more than 1024 fixtures");
}

TEST(LightsFixtures, PacksEachTypeThroughTheMaster) {
  const Patch patch = parsePatch(R"({"fixtures": [
    {"type": "rgb", "universe": 1, "address": 1, "signal": "bloom.phase"},
    {"type": "rgbw", "universe": 1, "address": 4, "signal": "bloom.phase"},
    {"type": "dimmer", "universe": 1, "address": 8, "signal": "bloom.chamber"},
    {"type": "pixels", "count": 4, "universe": 2, "address": 10, "signal": "regions"},
    {"type": "rgb", "universe": 2, "address": 100, "signal": "regions", "index": 1},
    {"type": "rgb", "universe": 2, "address": 103, "signal": "neon.tubes"}]})", "p");
  Signals signals;
  signals.set("bloom.phase", {glm::vec3(1.0f, 0.5f, 0.25f)});
  signals.set("bloom.chamber", 0.5f);
  signals.set("regions", {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0)});
  const Universes full = pack(patch, lightColours(patch, signals, 1.0f));
  ASSERT_EQ(full.size(), 2u);
  const Universe& one = full.at(1);
  EXPECT_EQ((std::vector<int>(one.begin(), one.begin() + 8)), (std::vector<int>{255, 128, 64, 191, 64, 0, 64, 128}));
  const Universe& two = full.at(2);
  // A strip of 4 over 2 regions: two pixels each.
  EXPECT_EQ((std::vector<int>(two.begin() + 9, two.begin() + 21)), (std::vector<int>{255, 0, 0, 255, 0, 0, 0, 255, 0, 0, 255, 0}));
  EXPECT_EQ((std::vector<int>(two.begin() + 99, two.begin() + 105)), (std::vector<int>{0, 255, 0, 0, 0, 0}));  // neon: not published
  EXPECT_EQ(two[8], 0);
  const Universes half = pack(patch, lightColours(patch, signals, 0.5f));
  EXPECT_EQ(half.at(1)[0], 128);
  EXPECT_EQ(half.at(1)[7], 64);
}

TEST(LightsFixtures, SixteenBitPairsAndTheDmxSources) {
  EXPECT_FLOAT_EQ(pairLevel(255, 255), 1.0f);
  EXPECT_FLOAT_EQ(pairLevel(0, 0), 0.0f);
  EXPECT_NEAR(pairLevel(128, 0), 0.50001f, 1e-5f);
  for (float level : {0.0f, 0.25f, 0.3333f, 0.999f, 1.0f}) {
    const auto pair = levelPair(level);
    EXPECT_NEAR(pairLevel(pair[0], pair[1]), level, 1.0f / 65535.0f);
  }
  live::SourceBank bank;
  DmxSources sources;
  Universe u{};
  u[0] = 255, u[9] = 0x12, u[10] = 0x34;
  sources.apply(7, u, bank);
  EXPECT_FLOAT_EQ(bank.value("dmx.7.1"), 1.0f);
  EXPECT_FLOAT_EQ(bank.value("dmx.7.10"), float(0x12) / 255.0f);
  EXPECT_FLOAT_EQ(bank.value("dmx16.7.10"), float(0x1234) / 65535.0f);
  EXPECT_EQ(bank.values().count("dmx.7.2"), 0u);  // a channel at rest is not named
  u[10] = 0x35;
  sources.apply(7, u, bank);
  EXPECT_FLOAT_EQ(bank.value("dmx16.7.10"), float(0x1235) / 65535.0f);
  EXPECT_EQ(universesRead({"dmx.3.1", "dmx16.12.5", "dmx.3.9", "midi.cc.1.1", "dmx.x.1"}), (std::vector<uint32_t>{3, 12}));
}

TEST(LightsSources, NamesTakeoverAndLearn) {
  EXPECT_EQ(live::checkSourceName("dmx.0.1"), "");
  EXPECT_EQ(live::checkSourceName("dmx.65535.512"), "");
  EXPECT_EQ(live::checkSourceName("dmx16.1.511"), "");
  for (const char* bad : {"dmx.1.0", "dmx.1.513", "dmx16.1.512", "dmx.65536.1", "dmx.1", "dmx.01.1"})
    EXPECT_NE(live::checkSourceName(bad).find("DMX sources are dmx.UNIVERSE.CHANNEL"), std::string::npos) << bad;
  std::string why;
  EXPECT_EQ(live::parseMapping("dmx.1.5=kifs.fold", &why)->takeoverMode(), live::Takeover::Soft);
  EXPECT_EQ(live::parseMapping("dmx16.1.5=kifs.fold", &why)->takeoverMode(), live::Takeover::Soft);
  // A desk's fader is learnt like a MIDI knob.
  host::LiveLink link(host::LiveConfig{});
  link.readInputs(0.0);
  link.sources().set("dmx.2.40", 0.6f);
  link.sources().set("midi.cc.1.1", 0.1f);
  link.readInputs(0.1);
  EXPECT_EQ(link.takeMovedControl(), "dmx.2.40");
}

TEST(LightsSources, SoftTakeoverOfAFader) {
  const SceneInfo& kifs = *findScene("kifs");
  kifs::Settings settings;
  settings.fold = 1.2f;
  live::Modulator modulator;
  std::string why;
  modulator.setMappings(kifs, {*live::parseMapping("dmx.1.1=kifs.fold:1:1.3", &why)});
  live::SourceBank bank;
  const auto step = [&] {
    const live::Modulated out = modulator.step(bank, params::Bound{&kifs::schema(), &settings}, 1.0f / 60.0f);
    for (const auto& [key, value] : out.values) kifs::schema().find(key)->parse(&settings, value, nullptr);
  };
  bank.set("dmx.1.1", 0.0f);  // the fader is down: the parameter stays
  step();
  EXPECT_FLOAT_EQ(settings.fold, 1.2f);
  bank.set("dmx.1.1", 1.0f);  // pushed up through the value: it takes over
  step();
  EXPECT_FLOAT_EQ(settings.fold, 1.3f);
}

SmallFrame halves(glm::vec3 left, glm::vec3 right, uint32_t width = 16, uint32_t height = 4) {
  SmallFrame frame{width, height, {}};
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) frame.pixels.push_back(x < width / 4 ? left : right);
  return frame;
}

TEST(LightsColours, RegionMeansAndDominantColours) {
  const SmallFrame frame = halves(glm::vec3(1, 0, 0), glm::vec3(0, 0, 1));
  const auto two = regionMeans(frame, 2, 1);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_NEAR(two[0].r, 0.5f, 1e-6f);  // a quarter red: half of the left region
  EXPECT_NEAR(two[1].b, 1.0f, 1e-6f);
  const auto fine = regionMeans(frame, 32, 8);  // finer than the frame: the pixel under each centre
  ASSERT_EQ(fine.size(), 256u);
  EXPECT_EQ(fine[0], glm::vec3(1, 0, 0));
  EXPECT_EQ(fine[31], glm::vec3(0, 0, 1));
  const auto clusters = dominantColours(frame, 4);
  ASSERT_EQ(clusters.size(), 2u);  // two colours in the frame
  EXPECT_EQ(clusters[0].colour, glm::vec3(0, 0, 1));
  EXPECT_FLOAT_EQ(clusters[0].share, 0.75f);
  EXPECT_EQ(clusters[1].colour, glm::vec3(1, 0, 0));
  // Three blobs with noise: three clusters, each near its blob.
  SmallFrame noisy{30, 1, {}};
  for (int i = 0; i < 30; ++i) {
    const float n = 0.02f * float(i % 3);
    noisy.pixels.push_back(i < 15 ? glm::vec3(0.9f - n, 0.1f, 0.1f) : i < 25 ? glm::vec3(0.1f, 0.8f + n, 0.1f) : glm::vec3(n));
  }
  const auto three = dominantColours(noisy, 3);
  ASSERT_EQ(three.size(), 3u);
  EXPECT_NEAR(three[0].colour.r, 0.88f, 0.02f);
  EXPECT_NEAR(three[1].colour.g, 0.82f, 0.02f);
  EXPECT_NEAR(three[2].colour.r, 0.02f, 0.02f);
}

TEST(LightsGuard, ALightFlashesAtMostThreeTimesASecond) {
  LightGuard guard;
  std::vector<float> shownAt;  // the times of the transitions shown
  glm::vec3 last(0.0f);
  const float dt = 1.0f / 44.0f;
  for (int frame = 0; frame < 440; ++frame) {  // 10 s of white and black at 22 Hz, on one light
    const glm::vec3 wanted = frame % 2 ? glm::vec3(1.0f) : glm::vec3(0.0f);
    const glm::vec3 shown = guard.limit({wanted}, dt)[0];
    if (shown != last) shownAt.push_back(float(frame) * dt);
    last = shown;
  }
  ASSERT_GT(shownAt.size(), 30u);  // it still changes, about 6 times a second
  for (size_t i = host::flash::kMaxTransitions; i < shownAt.size(); ++i)
    EXPECT_GT(shownAt[i] - shownAt[i - host::flash::kMaxTransitions], 1.0f) << "transition " << i;
  EXPECT_GT(guard.held(), 150u);  // of the 440 changes asked for, at most 6 a second shown
  // A saturated red against dark red counts as a red flash though its luminance hardly changes.
  LightGuard red;
  int redShown = 0;
  glm::vec3 redLast(0.1f, 0.0f, 0.0f);
  for (int frame = 0; frame < 44; ++frame) {
    const glm::vec3 shown = red.limit({frame % 2 ? glm::vec3(0.35f, 0.0f, 0.0f) : glm::vec3(0.1f, 0.0f, 0.0f)}, dt)[0];
    redShown += shown != redLast ? 1 : 0;
    redLast = shown;
  }
  EXPECT_LE(redShown, host::flash::kMaxTransitions + 1);
  // Blackout goes dark at once, whatever the window says; slow fades are never held.
  LightGuard dark;
  for (int frame = 0; frame < 20; ++frame) dark.limit({frame % 2 ? glm::vec3(1.0f) : glm::vec3(0.0f)}, dt);
  EXPECT_EQ(dark.limit({glm::vec3(1.0f)}, dt, /*dark=*/true)[0], glm::vec3(0.0f));
  LightGuard fade;
  for (int frame = 0; frame <= 100; ++frame)
    EXPECT_EQ(fade.limit({glm::vec3(float(frame) / 100.0f)}, dt)[0], glm::vec3(float(frame) / 100.0f));
}

}  // namespace
}  // namespace vitrine::lights
