// A recording's manifest (FOLDER/record.json): what a resume must agree with, so that two films are
// never mixed in one numbered sequence.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/error.h"
#include "host/offline/record_manifest.h"
#include "support/temp_folder.h"

namespace vitrine::host {
namespace {

RecordManifest neonFilm() {
  return {"neon", 96, 54, 30.0, 1, 0, 0.0, false, "exr", "", {{"bloom", "0.6"}, {"tubes", "12"}}};
}

std::string refusal(const std::filesystem::path& folder, const RecordManifest& run, bool frames) {
  try {
    claimFolder(folder, run, frames);
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(RecordManifest, ReadsBackWhatItWrites) {
  RecordManifest film = neonFilm();
  film.fps = 23.976;
  film.time = -1.5;
  film.input = fingerprint("0.5 down\n");
  film.reducedMotion = true;
  film.flashGuard = true;
  EXPECT_EQ(parseManifest(manifestText(film), "record.json"), film);
  EXPECT_EQ(fingerprint("0.5 down\n").size(), 16u);
  EXPECT_NE(fingerprint("0.5 down\n"), fingerprint("0.5 up\n"));
}

// A film's filters: which files in which order and their inputs' values are read back, and a resume
// with another value or another chain is told which.
TEST(RecordManifest, KeepsTheFiltersAndTheirValues) {
  RecordManifest film = neonFilm();
  film.filters = {"invert 0123456789abcdef", "gain fedcba9876543210"};
  film.filterValues = {{"filter.gain.gain", "0.5"}, {"filter.invert.amount", "1"}};
  EXPECT_EQ(parseManifest(manifestText(film), "record.json"), film);
  RecordManifest other = film;
  other.filterValues[1].second = "0.25";
  EXPECT_EQ(manifestDifferences(film, other),
            (std::vector<std::string>{"filter.invert.amount: 1 in the folder, 0.25 in this run"}));
  other = film;
  std::swap(other.filters[0], other.filters[1]);
  EXPECT_EQ(manifestDifferences(film, other),
            (std::vector<std::string>{"filters: invert 0123456789abcdef, gain fedcba9876543210 in the folder, gain "
                                      "fedcba9876543210, invert 0123456789abcdef in this run"}));
  EXPECT_EQ(parseManifest(manifestText(neonFilm()), "record.json").filters.size(), 0u);  // a film without filters
}

// Numbers no film has (a hand-edited record.json) are refused by name, before encode turns them into
// "inf s of sound" or a height of 4294967242.
TEST(RecordManifest, RefusesNumbersNoFilmHas) {
  const std::string good = manifestText(neonFilm());
  const auto with = [&](const std::string& from, const std::string& to) -> std::string {
    std::string text = good;
    const size_t at = text.find(from);
    if (at == std::string::npos) return "no " + from + " in " + text;
    text.replace(at, from.size(), to);
    try {
      (void)parseManifest(text, "record.json");
    } catch (const Error& e) {
      return e.what();
    }
    return "accepted";
  };
  const auto refuses = [&](const std::string& from, const std::string& to, const std::string& why) {
    const std::string said = with(from, to);
    EXPECT_NE(said.find(why), std::string::npos) << to << ": " << said;
  };
  refuses("\"fps\": 30.0", "\"fps\": 0", "(fps 0: frames a second are above 0 and at most 1000)");
  refuses("\"fps\": 30.0", "\"fps\": 1e300", "(fps 1e+300: frames a second are above 0 and at most 1000)");
  refuses("\"height\": 54", "\"height\": -54", "(height -54: a whole number from 1 to 65536)");
  refuses("\"width\": 96", "\"width\": 0", "(width 0: a whole number from 1 to 65536)");
  refuses("\"width\": 96", "\"width\": 96.5", "(width 96.5: a whole number from 1 to 65536)");
  refuses("\"spp\": 1", "\"spp\": 0", "(spp 0: a whole number from 1 to 256)");
  refuses("\"seed\": 0", "\"seed\": -1", "(seed -1: a whole number from 0 to 4294967295)");
  EXPECT_EQ(with("\"fps\": 30.0", "\"fps\": 24"), "accepted");
}

TEST(RecordManifest, NamesEveryDifference) {
  const RecordManifest film = neonFilm();
  EXPECT_TRUE(manifestDifferences(film, film).empty());
  RecordManifest other = film;
  other.width = 160, other.height = 90, other.spp = 4, other.seed = 7;
  other.values = {{"bloom", "0.8"}, {"tubes", "12"}};
  EXPECT_EQ(manifestDifferences(film, other),
            (std::vector<std::string>{"size: 96x54 in the folder, 160x90 in this run", "spp: 1 in the folder, 4 in this run",
                                      "seed: 0 in the folder, 7 in this run", "bloom: 0.6 in the folder, 0.8 in this run"}));
  other = film;
  other.scene = "kifs";  // another scene: its parameters are another set altogether, the scene says it
  other.values = {{"step", "9"}};
  EXPECT_EQ(manifestDifferences(film, other), std::vector<std::string>{"scene: neon in the folder, kifs in this run"});
  other = film;
  other.flashGuard = true;  // the guard changes the frames: a resume must not mix them
  EXPECT_EQ(manifestDifferences(film, other), std::vector<std::string>{"flash guard: off in the folder, on in this run"});
}

class RecordFolder : public test::TempFolderTest {};

TEST_F(RecordFolder, TheFirstRunWritesTheManifestAndAResumeMustAgree) {
  EXPECT_EQ(refusal(folder_, neonFilm(), false), "accepted");
  ASSERT_TRUE(std::filesystem::exists(manifestPath(folder_)));
  EXPECT_EQ(refusal(folder_, neonFilm(), true), "accepted");  // the same film: resumed
  RecordManifest kifs = neonFilm();
  kifs.scene = "kifs", kifs.width = 160, kifs.height = 90;
  const std::string why = refusal(folder_, kifs, true);
  EXPECT_NE(why.find("holds another film"), std::string::npos) << why;
  EXPECT_NE(why.find("scene: neon in the folder, kifs in this run"), std::string::npos) << why;
  EXPECT_NE(why.find("size: 96x54 in the folder, 160x90 in this run"), std::string::npos) << why;
  EXPECT_EQ(parseManifest(manifestText(neonFilm()), "x"), neonFilm()) << "the folder's manifest is left as it was";
}

TEST_F(RecordFolder, FramesWithoutAManifestAreNotResumedInto) {
  const std::string why = refusal(folder_, neonFilm(), true);
  EXPECT_NE(why.find("holds frames but no record.json"), std::string::npos) << why;
  EXPECT_FALSE(std::filesystem::exists(manifestPath(folder_)));
}

TEST_F(RecordFolder, AManifestThatIsNotOneIsRefusedByName) {
  std::ofstream(manifestPath(folder_)) << "{\"vitrine_record\": 1, \"scene\": 3}";
  const std::string why = refusal(folder_, neonFilm(), true);
  EXPECT_NE(why.find("record.json is not a recording's manifest"), std::string::npos) << why;
}

}  // namespace
}  // namespace vitrine::host
