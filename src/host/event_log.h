#pragma once
// Scene events: named happenings with values that a scene reports ("stage_changed", stage=3), for
// tests to check and headless runs to record (--events FILE). The file holds one compact JSON object
// per line, keys in this order: {"t": seconds, "scene": "...", "event": "...", then the values}.
//
// The value types and the sink are in namespace vitrine, beside CursorInput, because scenes use them;
// the sinks themselves are the host's.
#include <concepts>
#include <filesystem>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace vitrine {

template <typename T>
concept EventNumber = std::is_arithmetic_v<T> && !std::same_as<T, bool>;

// A number, a string or a bool. Every arithmetic type converts to a number and a string literal to a
// string, so `{"count", 3}` and `{"label", "fold"}` just work (a bare std::variant would refuse the int
// as narrowing and is one rule change away from taking the literal as a bool).
struct EventValue {
  std::variant<double, std::string, bool> value;

  EventValue(bool flag) : value(flag) {}
  EventValue(EventNumber auto number) : value(static_cast<double>(number)) {}
  EventValue(std::string text) : value(std::move(text)) {}
  EventValue(std::string_view text) : value(std::string(text)) {}
  EventValue(const char* text) : value(std::string(text)) {}
  bool operator==(const EventValue&) const = default;
};

struct SceneEvent {
  std::string name;
  std::vector<std::pair<std::string, EventValue>> values;  // written in this order

  const EventValue* find(std::string_view key) const;  // nullptr when there is no such value
  bool operator==(const SceneEvent&) const = default;
};

// Throws vitrine::Error when the event has no name, or a value is named "t", "scene" or "event" (the
// line's own keys) or twice: either would silently drop a value from the JSON object, so both are bugs
// to catch in a scene's test, not data to rename.
void checkSceneEvent(const SceneEvent& event);

class EventSink {
 public:
  virtual ~EventSink() = default;
  // `time`: the simulation time of the step that raised the event. Throws as checkSceneEvent does.
  virtual void emit(double time, std::string_view scene, const SceneEvent& event) = 0;
};

}  // namespace vitrine

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
