// The parameter table: every kind's parse and canonical text, the range checks every front end shares,
// batches judged once on their final values, presets, declaration mistakes and the --list-params text.
#include "params/listing.h"
#include "params/schema.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <stdexcept>

namespace vitrine::params {
namespace {

enum class Shape { Round, Square, Star };

struct Grid {
  int x = 32, y = 32, z = 8;
  bool operator==(const Grid&) const = default;
};

// "N" (a cube) or "WxHxD", sides 1..4096, like noodles' grid.
bool parseGrid(std::string_view text, Grid& grid, std::string* error) {
  int sides[3] = {};
  int count = 0;
  size_t begin = 0;
  while (true) {
    const size_t end = text.find('x', begin);
    if (count == 3 || !parseIntText(text.substr(begin, end - begin), 1, 4096, sides[count++], nullptr)) {
      *error = "expected N or WxHxD with sides from 1 to 4096";
      return false;
    }
    if (end == std::string_view::npos) break;
    begin = end + 1;
  }
  if (count == 2) {
    *error = "expected N or WxHxD with sides from 1 to 4096";
    return false;
  }
  grid = count == 1 ? Grid{sides[0], sides[0], sides[0]} : Grid{sides[0], sides[1], sides[2]};
  return true;
}

std::string formatGrid(const Grid& grid) { return fmt::format("{}x{}x{}", grid.x, grid.y, grid.z); }

struct Demo {
  float scale = 0.5f;
  float fine = 0.05f;
  int steps = 9;
  bool stripe = false;
  Shape shape = Shape::Square;
  bool msaa = true;  // a choice over a bool: "off" / "4x"
  Grid grid;
  float a = 1.0f, b = 1.0f;
  float drag = 0.0f;
};

Schema demoSchema() {
  auto schema = Schema::forStruct<Demo>();
  schema.add(floatParam({.key = "scale", .label = "scale", .help = "Noise scale.", .group = "", .flags = kLogarithmic},
                        &Demo::scale, 0.001, 10.0));
  schema.add(floatParam({.key = "fine", .help = "A small step."}, &Demo::fine, 0.0001, 1.0));
  schema.add(intParam({.key = "steps", .help = "Stage of the build-up."}, &Demo::steps, 1, 9));
  schema.add(boolParam({.key = "stripe", .help = "Paint one side.", .group = "look"}, &Demo::stripe));
  schema.add(choiceParam({.key = "shape", .help = "The outline.", .group = "look"}, &Demo::shape,
                         {"round", "square", "star"}));
  schema.add(choiceParam({.key = "msaa", .group = "look"}, &Demo::msaa, {"off", "4x"}));
  schema.add(customParam<Demo, Grid>({.key = "grid", .help = "Strands per axis.", .group = "layout", .flags = kRebuilds},
                                     &Demo::grid, parseGrid, formatGrid));
  schema.add(floatParam({.key = "a", .group = "layout"}, &Demo::a, 0.0, 1000.0));
  schema.add(floatParam({.key = "b", .group = "layout"}, &Demo::b, 0.0, 1000.0));
  schema.add(floatParam({.key = "drag", .help = "Camera nudge.", .flags = kTransient}, &Demo::drag, -100.0, 100.0));
  schema.preset({.name = "calm", .help = "Slow and round.", .values = {{"scale", "0.25"}, {"shape", "round"}}});
  schema.preset({.name = "dense", .help = "Many strands.", .values = {{"grid", "64"}, {"steps", "3"}}});
  return schema;
}

const Schema& schema() {
  static const Schema instance = demoSchema();
  return instance;
}

// "a*b <= 100": a check only the final values of a batch can be judged by.
std::string productCheck(const Demo& demo) {
  return demo.a * demo.b <= 100.0f ? std::string() : fmt::format("a*b = {} is above 100", demo.a * demo.b);
}

// Parses one value into a fresh Demo through the table; the error text, empty on success.
std::string parseOne(std::string_view key, std::string_view text, Demo* out = nullptr) {
  Demo demo;
  std::string error;
  const Param* param = schema().find(key);
  EXPECT_NE(param, nullptr) << key;
  if (!param->parse(&demo, text, &error)) return error.empty() ? "(refused without a reason)" : error;
  if (out) *out = demo;
  return {};
}

TEST(ParamsSchema, DefaultsComeFromTheStruct) {
  EXPECT_EQ(schema().find("scale")->defaultText, "0.5");
  EXPECT_EQ(schema().find("fine")->defaultText, "0.05");  // shortest float text, not 0.050000001
  EXPECT_EQ(schema().find("steps")->defaultText, "9");
  EXPECT_EQ(schema().find("stripe")->defaultText, "off");
  EXPECT_EQ(schema().find("shape")->defaultText, "square");
  EXPECT_EQ(schema().find("msaa")->defaultText, "4x");
  EXPECT_EQ(schema().find("grid")->defaultText, "32x32x8");
  EXPECT_EQ(schema().find("missing"), nullptr);
}

TEST(ParamsSchema, EveryKindParsesAndFormats) {
  Demo demo;
  const Bound bound = bindSettings(schema(), demo);
  EXPECT_EQ(applyValues(bound, {{"scale", "2.5"}, {"steps", "3"}, {"stripe", "on"}, {"shape", "star"}, {"msaa", "off"},
                          {"grid", "64x16x4"}}),
            "");
  EXPECT_EQ(demo.scale, 2.5f);
  EXPECT_EQ(demo.steps, 3);
  EXPECT_TRUE(demo.stripe);
  EXPECT_EQ(demo.shape, Shape::Star);
  EXPECT_FALSE(demo.msaa);
  EXPECT_EQ(demo.grid, (Grid{64, 16, 4}));

  const auto text = [&](std::string_view key) { return schema().find(key)->format(&demo); };
  EXPECT_EQ(text("scale"), "2.5");
  EXPECT_EQ(text("steps"), "3");
  EXPECT_EQ(text("stripe"), "on");
  EXPECT_EQ(text("shape"), "star");
  EXPECT_EQ(text("msaa"), "off");
  EXPECT_EQ(text("grid"), "64x16x4");

  const auto number = [&](std::string_view key) { return schema().find(key)->number(&demo); };
  EXPECT_EQ(number("scale"), 2.5);
  EXPECT_EQ(number("steps"), 3.0);
  EXPECT_EQ(number("stripe"), 1.0);
  EXPECT_EQ(number("shape"), 2.0);
  EXPECT_EQ(number("msaa"), 0.0);
  EXPECT_FALSE(schema().find("grid")->number);  // Custom has no number
}

TEST(ParamsSchema, CanonicalTextRoundTrips) {
  Demo demo;
  EXPECT_EQ(parseOne("scale", "0.1", &demo), "");
  EXPECT_EQ(schema().find("scale")->format(&demo), "0.1");
  EXPECT_EQ(parseOne("scale", "1e-3", &demo), "");
  EXPECT_EQ(schema().find("scale")->format(&demo), "0.001");
  EXPECT_EQ(parseOne("scale", "10.000", &demo), "");
  EXPECT_EQ(schema().find("scale")->format(&demo), "10");
  EXPECT_EQ(parseOne("grid", "16", &demo), "");  // a cube
  EXPECT_EQ(schema().find("grid")->format(&demo), "16x16x16");
  EXPECT_EQ(formatFloat(1.0f / 3.0f), "0.33333334");
  EXPECT_EQ(formatFloat(100.0f), "100");
}

TEST(ParamsSchema, FloatRefusesWhatIsNotAFiniteNumberInRange) {
  const std::string expected = "expected a number from 0.001 to 10";
  for (const char* text : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e308", "-1e308", "1e39", "", " ", "0x10",
                           "0.5x", " 0.5", "0.5 ", "+0.5", "0,5", "1e", "--1", "0.0009", "10.001", "-1", "0"})
    EXPECT_EQ(parseOne("scale", text), expected) << "'" << text << "'";
  for (const char* text : {"0.001", "10", "5", "1e0", "0.5000"}) EXPECT_EQ(parseOne("scale", text), "") << text;
  // The range is checked in float: the bound itself is accepted though 0.0001f < 0.0001 as doubles.
  EXPECT_EQ(parseOne("fine", "0.0001"), "");
  EXPECT_EQ(parseOne("fine", "0.00009"), "expected a number from 0.0001 to 1");
}

TEST(ParamsSchema, IntRefusesWhatIsNotAWholeNumberInRange) {
  const std::string expected = "expected a whole number from 1 to 9";
  for (const char* text : {"", "0", "10", "-1", "1.0", "1e1", "0x10", "3 ", " 3", "+3", "3x", "nan", "99999999999999"})
    EXPECT_EQ(parseOne("steps", text), expected) << "'" << text << "'";
  for (const char* text : {"1", "9", "5"}) EXPECT_EQ(parseOne("steps", text), "") << text;
}

TEST(ParamsSchema, BoolTakesOnOffTrueFalseOneZero) {
  Demo demo;
  for (const char* text : {"on", "true", "1"}) {
    EXPECT_EQ(parseOne("stripe", text, &demo), "");
    EXPECT_TRUE(demo.stripe) << text;
  }
  for (const char* text : {"off", "false", "0"}) {
    demo.stripe = true;
    EXPECT_EQ(parseOne("stripe", text, &demo), "");
    EXPECT_FALSE(demo.stripe) << text;
  }
  for (const char* text : {"", "yes", "ON", "2", "onn", " on"}) EXPECT_EQ(parseOne("stripe", text), "expected on or off") << text;
}

TEST(ParamsSchema, ChoiceTakesItsNamesOnly) {
  for (const char* text : {"", "triangle", "Round", "0", "2", "round "})
    EXPECT_EQ(parseOne("shape", text), "expected one of: round square star") << text;
  EXPECT_EQ(parseOne("msaa", "8x"), "expected one of: off 4x");
}

TEST(ParamsSchema, CustomUsesItsParserAndLeavesTheFieldOnFailure) {
  Demo demo;
  demo.grid = {5, 6, 7};
  const Bound bound = bindSettings(schema(), demo);
  for (const char* text : {"", "0", "4097", "8x8", "8x8x8x8", "8xx8", "axbxc", "8x8x"})
    EXPECT_EQ(applyValues(bound, {{"grid", text}}), fmt::format("grid={}: expected N or WxHxD with sides from 1 to 4096", text));
  EXPECT_EQ(demo.grid, (Grid{5, 6, 7}));
  EXPECT_EQ(applyValues(bound, {{"grid", "32x32x8"}}), "");
  EXPECT_EQ(demo.grid, (Grid{32, 32, 8}));
}

TEST(ParamsSchema, ColourIsHashRrGgBbAndRoundTrips) {
  struct Paint {
    glm::vec3 colour = params::hexColour(0xff3399);
  };
  auto schema = params::Schema::forStruct<Paint>();
  schema.add(params::colourParam<Paint>({"colour", "colour", "A colour.", ""}, &Paint::colour));
  Paint paint;
  const params::Param& param = *schema.find("colour");
  EXPECT_EQ(param.defaultText, "#ff3399");
  EXPECT_EQ(param.typeName(), "colour #rrggbb");
  EXPECT_TRUE(param.parse(&paint, "#00FF80", nullptr));
  EXPECT_EQ(param.format(&paint), "#00ff80");
  EXPECT_FLOAT_EQ(paint.colour.g, 1.0f);
  std::string error;
  for (const char* bad : {"00ff80", "#00ff8", "#00ff800", "#00gg80", "red", ""}) {
    EXPECT_FALSE(param.parse(&paint, bad, &error)) << bad;
    EXPECT_EQ(param.format(&paint), "#00ff80") << "a refused colour must leave the field";
  }
  EXPECT_EQ(error, "expected a colour as #rrggbb");
}

TEST(ParamsSchema, TypeNames) {
  EXPECT_EQ(schema().find("scale")->typeName(), "float 0.001..10");
  EXPECT_EQ(schema().find("steps")->typeName(), "int 1..9");
  EXPECT_EQ(schema().find("stripe")->typeName(), "bool");
  EXPECT_EQ(schema().find("shape")->typeName(), "choice round|square|star");
  EXPECT_EQ(schema().find("grid")->typeName(), "custom");
}

TEST(ParamsApply, BatchIsJudgedOnFinalValuesInEitherOrder) {
  Demo demo;
  const Bound bound = bindSettings(schema(), demo);
  const Check check = [&] { return productCheck(demo); };
  // a=1000 alone breaks a*b <= 100; with b=0.01 in the same batch it holds, whichever comes first.
  EXPECT_EQ(applyValues(bound, {{"a", "1000"}, {"b", "0.01"}}, check), "");
  EXPECT_EQ(demo.a, 1000.0f);
  resetToDefaults(bound);
  EXPECT_EQ(applyValues(bound, {{"b", "0.01"}, {"a", "1000"}}, check), "");
  EXPECT_EQ(demo.a, 1000.0f);
  EXPECT_EQ(demo.b, 0.01f);
}

TEST(ParamsApply, FailingCheckRestoresEverything) {
  Demo demo;
  const Bound bound = bindSettings(schema(), demo);
  const Check check = [&] { return productCheck(demo); };
  const KeyValues before = snapshot(bound);
  EXPECT_EQ(applyValues(bound, {{"steps", "2"}, {"a", "1000"}, {"grid", "4"}}, check), "a*b = 1000 is above 100");
  EXPECT_EQ(snapshot(bound), before);
  EXPECT_EQ(applyValues(bound, {{"steps", "2"}, {"a", "1000"}}, [] { return std::string(); }), "");
  EXPECT_EQ(demo.steps, 2);
}

TEST(ParamsApply, BadValueOrUnknownKeyRestoresEarlierValues) {
  Demo demo;
  const Bound bound = bindSettings(schema(), demo);
  const KeyValues before = snapshot(bound);
  EXPECT_EQ(applyValues(bound, {{"steps", "2"}, {"scale", "nan"}}), "scale=nan: expected a number from 0.001 to 10");
  EXPECT_EQ(snapshot(bound), before);
  const std::string unknown = applyValues(bound, {{"steps", "2"}, {"nope", "1"}});
  EXPECT_EQ(unknown.rfind("nope=1: unknown parameter; known: scale fine steps", 0), 0u) << unknown;
  EXPECT_EQ(snapshot(bound), before);
}

TEST(ParamsApply, ThrowingCheckRestoresAndRethrows) {
  Demo demo;
  const Bound bound = bindSettings(schema(), demo);
  EXPECT_THROW(applyValues(bound, {{"steps", "2"}}, []() -> std::string { throw std::runtime_error("boom"); }),
               std::runtime_error);
  EXPECT_EQ(demo.steps, 9);
}

TEST(ParamsApply, SnapshotApplyRoundTrip) {
  Demo demo;
  const Bound bound = bindSettings(schema(), demo);
  ASSERT_EQ(applyValues(bound, {{"scale", "0.3"}, {"fine", "0.123"}, {"steps", "4"}, {"stripe", "on"}, {"shape", "round"},
                          {"grid", "3x4x5"}, {"drag", "-2.5"}}),
            "");
  const KeyValues values = snapshot(bound);
  ASSERT_EQ(values.size(), schema().params().size());
  EXPECT_EQ(values[0], (std::pair<std::string, std::string>("scale", "0.3")));

  Demo other;
  ASSERT_EQ(applyValues(bindSettings(schema(), other), values), "");
  EXPECT_EQ(snapshot(bindSettings(schema(), other)), values);
  EXPECT_EQ(other.grid, demo.grid);
  EXPECT_EQ(other.fine, demo.fine);

  const KeyValues saved = snapshot(bound, false);  // what a settings file gets
  EXPECT_EQ(saved.size(), values.size() - 1);
  for (const auto& [key, text] : saved) EXPECT_NE(key, "drag");
}

TEST(ParamsApply, ResetPerKeyAndAll) {
  Demo demo;
  const Bound bound = bindSettings(schema(), demo);
  ASSERT_EQ(applyValues(bound, {{"steps", "2"}, {"shape", "star"}, {"a", "1000"}, {"b", "0.01"}}), "");
  EXPECT_EQ(resetToDefault(bound, "steps"), "");
  EXPECT_EQ(demo.steps, 9);
  EXPECT_EQ(demo.shape, Shape::Star);
  // Resetting b alone would make a*b = 1000: the check refuses it and nothing changes.
  const Check check = [&] { return productCheck(demo); };
  EXPECT_EQ(resetToDefault(bound, "b", check), "a*b = 1000 is above 100");
  EXPECT_EQ(demo.b, 0.01f);
  EXPECT_NE(resetToDefault(bound, "nope"), "");
  resetToDefaults(bound);
  Demo fresh;
  EXPECT_EQ(snapshot(bound), snapshot(bindSettings(schema(), fresh)));
}

TEST(ParamsApply, BindRefusesAnotherStruct) {
  struct Other {
    int x = 0;
  } other;
  EXPECT_THROW(bindSettings(schema(), other), std::logic_error);
}

TEST(ParamsPresets, ApplyAsOneBatch) {
  Demo demo;
  const Bound bound = bindSettings(schema(), demo);
  EXPECT_EQ(applyPreset(bound, "calm"), "");
  EXPECT_EQ(demo.scale, 0.25f);
  EXPECT_EQ(demo.shape, Shape::Round);
  EXPECT_EQ(demo.steps, 9);  // a preset is partial
  EXPECT_EQ(applyPreset(bound, "dense", [] { return std::string("too dense"); }), "too dense");
  EXPECT_EQ(demo.grid, (Grid{}));
  EXPECT_EQ(applyPreset(bound, "stormy"), "unknown preset 'stormy'; expected one of: calm dense");
}

TEST(ParamsDeclaration, MistakesThrowAtDeclaration) {
  struct S {
    int n = 0;
    int m = 5;
    float f = 2.0f;
    Shape shape = Shape(7);
  };
  auto schema = Schema::forStruct<S>();
  schema.add(intParam({.key = "m"}, &S::m, 1, 9));
  EXPECT_THROW(schema.add(intParam({.key = "m"}, &S::m, 1, 9)), std::logic_error);          // duplicate key
  EXPECT_THROW(schema.add(intParam({.key = "n"}, &S::n, 1, 9)), std::logic_error);          // default 0 out of range
  EXPECT_THROW(schema.add(floatParam({.key = "f"}, &S::f, 0.0, 1.0)), std::logic_error);    // default 2 out of range
  EXPECT_THROW(schema.add(choiceParam({.key = "shape"}, &S::shape, {"a", "b"})), std::logic_error);  // no name for 7
  EXPECT_THROW(schema.add(floatParam({.key = "scale"}, &Demo::scale, 0.0, 1.0)), std::logic_error);  // another struct
  EXPECT_THROW(schema.add(intParam({.key = ""}, &S::m, 1, 9)), std::logic_error);
  EXPECT_THROW(schema.add(intParam({.key = "a=b"}, &S::m, 1, 9)), std::logic_error);
  EXPECT_THROW(schema.add(intParam({.key = "lo"}, &S::m, 9, 1)), std::logic_error);  // min above max
  EXPECT_EQ(schema.params().size(), 1u);
  EXPECT_NO_THROW(schema.add(intParam({.key = "n"}, &S::n, 0, 9)));
}

TEST(ParamsDeclaration, BadPresetsThrow) {
  auto schema = demoSchema();
  EXPECT_THROW(schema.preset({.name = "x", .values = {{"nope", "1"}}}), std::logic_error);
  EXPECT_THROW(schema.preset({.name = "x", .values = {{"steps", "12"}}}), std::logic_error);
  EXPECT_THROW(schema.preset({.name = "x", .values = {{"scale", "nan"}}}), std::logic_error);
  EXPECT_THROW(schema.preset({.name = "calm", .values = {{"steps", "2"}}}), std::logic_error);  // duplicate
  EXPECT_THROW(schema.preset({.name = "", .values = {}}), std::logic_error);
  EXPECT_NO_THROW(schema.preset({.name = "x", .values = {{"steps", "2"}}}));
}

// The command line (apply), presets and a raw parse give the same answer for the same text.
TEST(ParamsSchema, EveryPathEnforcesTheSameRange) {
  for (const char* text : {"0.0009", "0.001", "10", "10.5", "nan", "1e308", "0.5", ""}) {
    const bool accepted = parseOne("scale", text).empty();
    Demo demo;
    EXPECT_EQ(applyValues(bindSettings(schema(), demo), {{"scale", text}}).empty(), accepted) << text;
    auto copy = demoSchema();
    bool presetAccepted = true;
    try {
      copy.preset({.name = "probe", .values = {{"scale", text}}});
    } catch (const std::logic_error&) {
      presetAccepted = false;
    }
    EXPECT_EQ(presetAccepted, accepted) << text;
  }
}

TEST(ParamsListing, ShowsKeysTypesDefaultsFlagsGroupsAndPresets) {
  const std::string text = describeSchema("demo", schema());
  for (const char* needle : {"demo", "scale", "float 0.001..10", "default 0.5", "Noise scale.", "int 1..9", "default 9",
                             "choice round|square|star", "default square", "[look]", "[layout]", "grid", "custom",
                             "default 32x32x8", "rebuilds", "not saved", "calm", "Slow and round.", "scale=0.25 shape=round",
                             "dense", "grid=64 steps=3"})
    EXPECT_NE(text.find(needle), std::string::npos) << needle << "\n" << text;
  // Ungrouped parameters lead; the groups follow in order of first use.
  EXPECT_LT(text.find("drag"), text.find("[look]"));
  EXPECT_LT(text.find("[look]"), text.find("[layout]"));
  // The columns line up: "default" starts at the same column on every parameter line.
  size_t column = std::string::npos;
  size_t lineStart = 0;
  while (lineStart < text.size()) {
    const size_t lineEnd = text.find('\n', lineStart);
    const std::string line = text.substr(lineStart, lineEnd - lineStart);
    if (const size_t at = line.find(" default "); at != std::string::npos) {
      if (column == std::string::npos) column = at;
      EXPECT_EQ(at, column) << line;
    }
    lineStart = lineEnd + 1;
  }
  EXPECT_NE(column, std::string::npos);
  EXPECT_EQ(text.back(), '\n');
}

}  // namespace
}  // namespace vitrine::params
