#pragma once
// Where scene events go (scenes/scene_events.h): the --events file, one compact JSON object per line,
// keys in this order: {"t": seconds, "scene": "...", "event": "...", then the values}; or memory, for tests.
#include "scenes/scene_events.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::host {

// One line of the --events file, without the newline. Whole numbers are written as integers ("frame":
// 3, not 3.0); NaN and infinities, which JSON lacks, as null.
std::string eventJsonLine(double time, std::string_view scene, const SceneEvent& event);

// The --events file. Lines are held in memory (a scene emits on changes, not per pixel) and written by
// close() through replaceAtomically: a run that fails before close() leaves any previous log as it was,
// never half a new one.
class JsonLinesEventLog final : public EventSink {
 public:
  explicit JsonLinesEventLog(std::filesystem::path path);  // fails now, not after the run, if unwritable
  void emit(double time, std::string_view scene, const SceneEvent& event) override;
  void close();  // writes the file, empty when nothing was emitted; later emits throw, a second close does nothing

 private:
  std::filesystem::path path_;
  std::string lines_;
  bool closed_ = false;
};

struct LoggedEvent {
  double time = 0.0;
  std::string scene;
  SceneEvent event;
};

// Collects events for tests; refuses the same events the file would.
class MemoryEventLog final : public EventSink {
 public:
  void emit(double time, std::string_view scene, const SceneEvent& event) override;
  const std::vector<LoggedEvent>& events() const { return events_; }
  void clear() { events_.clear(); }

 private:
  std::vector<LoggedEvent> events_;
};

}  // namespace vitrine::host
