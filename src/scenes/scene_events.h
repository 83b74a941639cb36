#pragma once
// Scene events: named happenings with values that a scene reports (a phase flip, a drag released),
// for tests to check and headless runs to record (--events FILE, host/event_log.h).
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

namespace vitrine {

// What a scene holds to report events: its sink (none in the gallery unless something listens) and
// its name, so a scene writes events.emit(input.time, {"flip", {{"phase", "amber"}}}).
class SceneEvents {
 public:
  SceneEvents() = default;
  SceneEvents(EventSink* sink, std::string_view scene) : sink_(sink), scene_(scene) {}
  void emit(double time, const SceneEvent& event) const {
    if (sink_) sink_->emit(time, scene_, event);
  }

 private:
  EventSink* sink_ = nullptr;
  std::string scene_;
};

}  // namespace vitrine
