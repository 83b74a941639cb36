// The size expressions of ISF passes: what they compute, and what they refuse.
#include "isf/isf_expression.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace vitrine::isf {
namespace {

double eval(const std::string& text, std::map<std::string, double> vars = {{"WIDTH", 1920}, {"HEIGHT", 1080}}) {
  const auto value = Expression::parse(text).evaluate([&](std::string_view name) -> std::optional<double> {
    const auto it = vars.find(std::string(name));
    return it == vars.end() ? std::nullopt : std::optional<double>(it->second);
  });
  EXPECT_TRUE(value.has_value()) << text;
  return value.value_or(std::numeric_limits<double>::quiet_NaN());
}

TEST(IsfExpression, TheSpecificationsExamples) {
  EXPECT_EQ(eval("$WIDTH/2.0"), 960.0);
  EXPECT_EQ(eval("floor($HEIGHT*0.5)+1"), 541.0);
  EXPECT_EQ(eval("max($WIDTH,$blurAmount*10)", {{"WIDTH", 1920}, {"blurAmount", 12}}), 1920.0);
  EXPECT_EQ(eval("max($WIDTH,$blurAmount*10)", {{"WIDTH", 1920}, {"blurAmount", 300}}), 3000.0);
}

TEST(IsfExpression, PrecedenceUnaryMinusAndFunctions) {
  EXPECT_EQ(eval("2+3*4"), 14.0);
  EXPECT_EQ(eval("(2+3)*4"), 20.0);
  EXPECT_EQ(eval("-(2+3)"), -5.0);
  EXPECT_EQ(eval("- -4"), 4.0);
  EXPECT_EQ(eval("10-4-3"), 3.0);   // left to right
  EXPECT_EQ(eval("64/4/2"), 8.0);
  EXPECT_EQ(eval("pow(2, 10)"), 1024.0);
  EXPECT_EQ(eval("sqrt(81) + abs(-1) + round(2.5) + ceil(0.2) + min(3, 1)"), 9.0 + 1 + 3 + 1 + 1);
  EXPECT_EQ(eval("1.5e2"), 150.0);
  EXPECT_EQ(eval(" 7 "), 7.0);
}

TEST(IsfExpression, ListsTheVariablesItReadsOnce) {
  const auto e = Expression::parse("$WIDTH*$scale+$WIDTH/$HEIGHT");
  EXPECT_EQ(e.variables(), (std::vector<std::string>{"WIDTH", "scale", "HEIGHT"}));
  EXPECT_FALSE(e.evaluate([](std::string_view) { return std::nullopt; }).has_value());
}

TEST(IsfExpression, RefusesWhatItDoesNotKnowWithTheReason) {
  auto reason = [](const std::string& text) {
    try {
      Expression::parse(text);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(reason("").find("ends where a value is expected"), std::string::npos);
  EXPECT_NE(reason("$").find("not followed by a name"), std::string::npos);
  EXPECT_NE(reason("WIDTH/2").find("written with '$'"), std::string::npos);
  EXPECT_NE(reason("system(1)").find("not a function it knows"), std::string::npos);
  EXPECT_NE(reason("floor(1, 2)").find("takes 1 argument, not 2"), std::string::npos);
  EXPECT_NE(reason("(1").find("')' is missing"), std::string::npos);
  EXPECT_NE(reason("1 2").find("'2' is not expected"), std::string::npos);
  EXPECT_NE(reason("1..2").find("not a number"), std::string::npos);
  EXPECT_NE(reason(std::string(300, '1')).find("at most 256"), std::string::npos);
  EXPECT_NE(reason(std::string(40, '(') + "1" + std::string(40, ')')).find("deeper than 32"), std::string::npos);
  EXPECT_NE(reason(std::string(40, '-') + "1").find("deeper than 32"), std::string::npos);
  EXPECT_EQ(reason(std::string(10, '(') + "1" + std::string(10, ')')), "accepted");
}

TEST(IsfExpression, SizesAreBoundedAndSayWhy) {
  std::string why;
  EXPECT_EQ(sizeFromValue(960.7, &why), 960);
  EXPECT_TRUE(why.empty());
  EXPECT_EQ(sizeFromValue(-5, &why), 1);
  EXPECT_NE(why.find("raised to 1"), std::string::npos);
  EXPECT_EQ(sizeFromValue(1e12, &why), kMaxTargetSide);
  EXPECT_NE(why.find("lowered to 16384"), std::string::npos);
  EXPECT_FALSE(sizeFromValue(std::nan(""), &why).has_value());
  EXPECT_NE(why.find("not a number"), std::string::npos);
  EXPECT_FALSE(sizeFromValue(eval("1/0"), &why).has_value());
  EXPECT_NE(why.find("infinite"), std::string::npos);
}

}  // namespace
}  // namespace vitrine::isf
