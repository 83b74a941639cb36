// Every rule of the command line: what is accepted, and the sentence for what is not.
#include "app/options.h"
#include "core/error.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace vitrine {
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

// ------------------------------------------------------------------------------------------- numbers

TEST(OptionsNumbers, TimeMustBeFinite) {
  for (const char* bad : {"nan", "NaN", "inf", "-inf", "infinity", "1e400"})
    EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--time", bad, "--out", "x.exr"}),
              fmt::format("--time expects a finite number of seconds, not '{}'.", bad));
  EXPECT_EQ(refusal({"--time", "soon"}), "--time expects a finite number of seconds, not 'soon'.");
  EXPECT_DOUBLE_EQ(parse({"--time", "-1.5"}).time, -1.5);
  EXPECT_DOUBLE_EQ(parse({"--time", "1e3"}).time, 1000.0);
}

TEST(OptionsNumbers, WholeNumbersNameTheirRange) {
  EXPECT_EQ(refusal({"--frames", "4294967296"}), "--frames expects a whole number from 1 to 4294967295, not '4294967296'.");
  EXPECT_EQ(refusal({"--frames", "0"}), "--frames expects a whole number from 1 to 4294967295, not '0'.");
  EXPECT_EQ(refusal({"--frames", "-1"}), "--frames expects a whole number from 1 to 4294967295, not '-1'.");
  EXPECT_EQ(refusal({"--frames", "2.5"}), "--frames expects a whole number from 1 to 4294967295, not '2.5'.");
  EXPECT_EQ(refusal({"--seed", "-1"}), "--seed expects a whole number from 0 to 4294967295, not '-1'.");
  EXPECT_EQ(refusal({"--seed", "x"}), "--seed expects a whole number from 0 to 4294967295, not 'x'.");
  EXPECT_EQ(refusal({"bench", "--warmup", "-3", "--json", "b.json"}),
            "--warmup expects a whole number from 0 to 4294967295, not '-3'.");
  EXPECT_EQ(parse({"--seed", "4294967295"}).seed, 4294967295u);
  EXPECT_EQ(parse({"--frames", "4294967295"}).frames, 4294967295u);
  EXPECT_EQ(parse({"bench", "--warmup", "0", "--json", "b.json"}).warmup, 0u);
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
  EXPECT_DOUBLE_EQ(parse({"--time", "-2"}).time, -2.0);  // a negative number is a value
}

TEST(OptionsValues, HeadlessWritesExrOrPng) {
  for (const char* bad : {"x.jpg", "x.txt", "x", "x.exr.bak"})
    EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", bad}),
              fmt::format("--out writes .exr (linear half float) or .png (8-bit sRGB), not '{}'.", bad));
  for (const char* good : {"x.exr", "x.png", "dir/x.EXR", "x.PNG"})
    EXPECT_EQ(refusal({"--headless", "--scene", "kifs", "--out", good}), "accepted") << good;
  EXPECT_EQ(refusal({"bench", "--json", "timings.txt"}), "accepted");  // any name for the JSON
}

}  // namespace
}  // namespace vitrine
