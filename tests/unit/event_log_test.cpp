// Scene events: the JSON line format, the atomic file log and the in-memory log for tests.
#include "host/event_log.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "support/temp_folder.h"
#include "support/files.h"

namespace vitrine::host {
namespace {

const SceneEvent kStage{"stage_changed", {{"stage", 3}, {"label", "fold"}, {"warped", true}, {"scale", 0.25f}}};

std::string errorOf(const SceneEvent& event) {
  try {
    eventJsonLine(0.0, "kifs", event);
  } catch (const Error& error) {
    return error.what();
  }
  return "(no error)";
}

TEST(EventLog, ValuesConvertToNumberStringOrBool) {
  EXPECT_EQ(EventValue(3).value, (std::variant<double, std::string, bool>(3.0)));
  EXPECT_EQ(EventValue(uint64_t(7)).value, (std::variant<double, std::string, bool>(7.0)));
  EXPECT_EQ(EventValue(0.5f).value, (std::variant<double, std::string, bool>(0.5)));
  EXPECT_EQ(EventValue("fold").value, (std::variant<double, std::string, bool>(std::string("fold"))));
  EXPECT_EQ(EventValue(std::string_view("fold")), EventValue(std::string("fold")));
  EXPECT_EQ(EventValue(false).value, (std::variant<double, std::string, bool>(false)));
  EXPECT_EQ(*kStage.find("label"), EventValue("fold"));
  EXPECT_EQ(kStage.find("missing"), nullptr);
}

TEST(EventLog, LineIsCompactJsonWithKeysInOrder) {
  EXPECT_EQ(eventJsonLine(0.5, "kifs", kStage),
            R"({"t":0.5,"scene":"kifs","event":"stage_changed","stage":3,"label":"fold","warped":true,"scale":0.25})");
  EXPECT_EQ(eventJsonLine(2.0, "noodles", SceneEvent{"reset", {}}), R"({"t":2,"scene":"noodles","event":"reset"})");
}

TEST(EventLog, LineRoundTripsThroughAParser) {
  const SceneEvent event{"hit",
                         {{"count", -12},
                          {"x", 0.1},
                          {"big", 1e300},
                          {"tiny", 1e-300},
                          {"frame", uint64_t(1) << 40},
                          {"quote", "say \"hi\"\n\tand \\ go"},
                          {"unicode", "café ✓"},
                          {"on", true},
                          {"off", false},
                          {"nan", std::nan("")},
                          {"inf", std::numeric_limits<double>::infinity()}}};
  const auto parsed = nlohmann::ordered_json::parse(eventJsonLine(1.0 / 3.0, "kifs", event));
  EXPECT_EQ(parsed["t"].get<double>(), 1.0 / 3.0);  // doubles are written to round-trip exactly
  EXPECT_EQ(parsed["scene"], "kifs");
  EXPECT_EQ(parsed["event"], "hit");
  EXPECT_EQ(parsed["count"].get<int>(), -12);
  EXPECT_EQ(parsed["x"].get<double>(), 0.1);
  EXPECT_EQ(parsed["big"].get<double>(), 1e300);
  EXPECT_EQ(parsed["tiny"].get<double>(), 1e-300);
  EXPECT_EQ(parsed["frame"].get<uint64_t>(), uint64_t(1) << 40);
  EXPECT_EQ(parsed["quote"], "say \"hi\"\n\tand \\ go");
  EXPECT_EQ(parsed["unicode"], "café ✓");
  EXPECT_EQ(parsed["on"], true);
  EXPECT_EQ(parsed["off"], false);
  EXPECT_TRUE(parsed["nan"].is_null());  // JSON has no NaN or infinity
  EXPECT_TRUE(parsed["inf"].is_null());
  std::vector<std::string> keys;
  for (const auto& item : parsed.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"t", "scene", "event", "count", "x", "big", "tiny", "frame", "quote",
                                            "unicode", "on", "off", "nan", "inf"}));
}

TEST(EventLog, BrokenUtf8IsReplacedNotFatal) {
  const auto line = eventJsonLine(0.0, "kifs", SceneEvent{"bad", {{"text", std::string("a\xff") + "b"}}});
  EXPECT_EQ(nlohmann::json::parse(line)["text"], "a\uFFFDb");
}

TEST(EventLog, RefusesUnnamedEventsAndValuesThatWouldBeLost) {
  EXPECT_EQ(errorOf(SceneEvent{"", {}}), "A scene event needs a name");
  for (const char* reserved : {"t", "scene", "event"})
    EXPECT_EQ(errorOf(SceneEvent{"hit", {{reserved, 1}}}),
              fmt::format("Scene event 'hit' has a value named '{}', which the log uses itself", reserved));
  EXPECT_EQ(errorOf(SceneEvent{"hit", {{"x", 1}, {"y", 2}, {"x", 3}}}), "Scene event 'hit' has two values named 'x'");
  MemoryEventLog memory;
  EXPECT_THROW(memory.emit(0.0, "kifs", SceneEvent{"hit", {{"t", 1}}}), Error);  // tests catch what the file refuses
  EXPECT_TRUE(memory.events().empty());
}

TEST(EventLog, MemoryLogCollectsInOrder) {
  MemoryEventLog log;
  log.emit(0.5, "kifs", kStage);
  log.emit(1.0, "noodles", SceneEvent{"reset", {}});
  ASSERT_EQ(log.events().size(), 2u);
  EXPECT_EQ(log.events()[0].time, 0.5);
  EXPECT_EQ(log.events()[0].scene, "kifs");
  EXPECT_EQ(log.events()[0].event, kStage);
  EXPECT_EQ(log.events()[1].event.name, "reset");
  log.clear();
  EXPECT_TRUE(log.events().empty());
}

// One folder per test: ctest runs these side by side (a shared folder made them remove each other's files).
using EventLogFiles = test::TempFolderTest;

TEST_F(EventLogFiles, WritesOneLinePerEventWhenClosed) {
  const auto path = folder_ / "events.jsonl";
  JsonLinesEventLog log(path);
  log.emit(0.5, "kifs", kStage);
  log.emit(1.0, "kifs", SceneEvent{"reset", {}});
  EXPECT_FALSE(std::filesystem::exists(path));  // nothing on disk until the run is done
  log.close();
  EXPECT_EQ(test::readFile(path),
            eventJsonLine(0.5, "kifs", kStage) + "\n" + eventJsonLine(1.0, "kifs", SceneEvent{"reset", {}}) + "\n");
  std::ifstream lines(path);
  int count = 0;
  for (std::string line; std::getline(lines, line); ++count) EXPECT_TRUE(nlohmann::json::accept(line)) << line;
  EXPECT_EQ(count, 2);
  log.close();  // a second close changes nothing
  EXPECT_THROW(log.emit(2.0, "kifs", kStage), Error);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder_), {}), 1);  // no temporary left behind
}

TEST_F(EventLogFiles, AnEmptyRunWritesAnEmptyFile) {
  const auto path = folder_ / "none.jsonl";
  JsonLinesEventLog(path).close();
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_EQ(test::readFile(path), "");
}

TEST_F(EventLogFiles, ARunThatNeverClosesLeavesThePreviousLog) {
  const auto path = folder_ / "events.jsonl";
  std::ofstream(path) << "previous\n";
  {
    JsonLinesEventLog log(path);
    log.emit(0.5, "kifs", kStage);
  }  // the run failed: destroyed without close()
  EXPECT_EQ(test::readFile(path), "previous\n");
  JsonLinesEventLog log(path);
  log.emit(0.5, "kifs", kStage);
  log.close();
  EXPECT_EQ(test::readFile(path), eventJsonLine(0.5, "kifs", kStage) + "\n");
}

TEST_F(EventLogFiles, RefusesAnUnwritablePathBeforeTheRun) {
  EXPECT_THROW(JsonLinesEventLog(folder_ / "missing" / "events.jsonl"), Error);
  EXPECT_THROW(JsonLinesEventLog{folder_}, Error);  // a folder
}

}  // namespace
}  // namespace vitrine::host
