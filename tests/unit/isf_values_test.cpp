// An ISF file's INPUTS as a parameter schema made at run time (docs/ISF.md's mapping table): every
// type's parameter, its range and default, what the shader is given, and what makes none.
#include "isf/isf_values.h"

#include "isf_test_files.h"

#include <gtest/gtest.h>

namespace vitrine::isf {
namespace {

using test::isfFile;

std::vector<std::string> keysOf(const params::Schema& schema) {
  std::vector<std::string> keys;
  for (const params::Param& param : schema.params()) keys.push_back(param.key);
  return keys;
}

TEST(IsfValues, EveryInputTypeMapsAsTheTableSays) {
  const Document doc = loadDocument(isfFile("every_input.fs"));
  const params::Schema schema = makeSchema(doc);
  // flash (event), wave (audio) and spectrum (audioFFT) make no parameter.
  EXPECT_EQ(keysOf(schema), (std::vector<std::string>{"invert", "bands", "speed", "centre", "tint", "photo"}));
  EXPECT_EQ(schema.find("invert")->kind, params::Kind::Bool);
  EXPECT_EQ(schema.find("bands")->choices, (std::vector<std::string>{"two", "four", "eight"}));
  EXPECT_EQ(schema.find("bands")->defaultText, "four");
  EXPECT_EQ(schema.find("speed")->kind, params::Kind::Float);
  EXPECT_EQ(schema.find("speed")->max, 4.0);
  EXPECT_TRUE(schema.find("centre")->has(params::kTransient));  // the only point2D: the drag's
  EXPECT_EQ(schema.find("centre")->defaultText, "0.5,0.5");
  EXPECT_EQ(schema.find("tint")->defaultText, "#ff9933");
  EXPECT_TRUE(schema.find("photo")->has(params::kNamesFile));
  EXPECT_EQ(schema.find("photo")->defaultText, "none");
  EXPECT_EQ(eventNames(doc), std::vector<std::string>{"flash"});
  EXPECT_EQ(dragPoint(doc), 4);
}

TEST(IsfValues, ValuesReachTheShadersNumbers) {
  const Document doc = loadDocument(isfFile("every_input.fs"));
  const params::Schema schema = makeSchema(doc);
  Values values = defaultValues(doc);
  EXPECT_EQ(values.inputs[2].number[0], 4.0f);  // bands: the VALUE, not its index
  const params::Bound bound = params::bindSettings(schema, values);
  EXPECT_EQ(params::applyValues(bound, {{"bands", "eight"}, {"centre", "0.1,0.9"}, {"invert", "on"}, {"tint", "#000000"}}), "");
  EXPECT_EQ(values.inputs[2].number[0], 8.0f);
  EXPECT_EQ(values.inputs[4].number[0], 0.1f);
  EXPECT_EQ(values.inputs[4].number[1], 0.9f);
  EXPECT_EQ(values.inputs[1].number[0], 1.0f);
  EXPECT_EQ(values.inputs[5].number[3], 1.0f);  // alpha kept
  EXPECT_NE(params::applyValues(bound, {{"speed", "5"}}), "");  // out of MIN..MAX
  EXPECT_NE(params::applyValues(bound, {{"centre", "2,0"}}), "");
  EXPECT_NE(params::remoteProblem(*schema.find("photo"), "/etc/passwd"), "");
  EXPECT_EQ(params::remoteProblem(*schema.find("photo"), "none"), "");
  params::resetToDefaults(bound);
  EXPECT_EQ(values.inputs[2].number[0], 4.0f);  // the file's DEFAULT, not a zero
}

TEST(IsfValues, AColourNotOpaqueGetsItsAlphaAndLabelsBecomeWords) {
  const Document doc = parseDocument(
      R"(/*{"INPUTS": [{"NAME": "glass", "TYPE": "color", "DEFAULT": [1, 0, 0, 0.25]},
                       {"NAME": "mode", "TYPE": "long", "VALUES": [0, 1, 2], "LABELS": ["Soft light", "Soft light", ""]},
                       {"NAME": "a", "TYPE": "point2D"}, {"NAME": "b", "TYPE": "point2D", "DEFAULT": [320, 240]}]}*/
void main() { gl_FragColor = glass; })",
      "alpha.fs");
  const params::Schema schema = makeSchema(doc);
  ASSERT_NE(schema.find("glass_alpha"), nullptr);
  EXPECT_EQ(schema.find("glass_alpha")->defaultText, "0.25");
  EXPECT_EQ(schema.find("mode")->choices, (std::vector<std::string>{"Soft_light", "Soft_light_2", "2"}));
  EXPECT_FALSE(schema.find("a")->has(params::kTransient));  // two point2Ds: neither is the drag's
  EXPECT_EQ(dragPoint(doc), -1);
  EXPECT_EQ(schema.find("b")->defaultText, "320,240");  // a range widened to hold the default
}

}  // namespace
}  // namespace vitrine::isf
