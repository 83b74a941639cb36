#include "host/event_log.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/output_path.h"

namespace vitrine::host {
namespace {

nlohmann::ordered_json number(double value) {
  constexpr double kExactIntegers = 9007199254740992.0;  // 2^53: every whole double below is exact
  if (std::trunc(value) == value && std::abs(value) < kExactIntegers) return static_cast<int64_t>(value);
  return value;  // nlohmann writes NaN and infinities as null
}

}  // namespace

std::string eventJsonLine(double time, std::string_view scene, const SceneEvent& event) {
  checkSceneEvent(event);
  nlohmann::ordered_json line;  // keeps insertion order: t, scene, event, then the values
  line["t"] = number(time);
  line["scene"] = scene;
  line["event"] = event.name;
  for (const auto& [key, value] : event.values)
    line[key] = std::visit(
        [](const auto& v) -> nlohmann::ordered_json {
          if constexpr (std::is_same_v<std::decay_t<decltype(v)>, double>)
            return number(v);
          else
            return v;
        },
        value.value);
  // A scene's string with broken UTF-8 is written with replacement characters rather than failing the run.
  return line.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

JsonLinesEventLog::JsonLinesEventLog(std::filesystem::path path) : path_(std::move(path)) { checkWritable(path_); }

void JsonLinesEventLog::emit(double time, std::string_view scene, const SceneEvent& event) {
  if (closed_) throw Error(fmt::format("Scene event '{}' arrived after {} was closed", event.name, path_.string()));
  lines_ += eventJsonLine(time, scene, event);
  lines_ += '\n';
}

void JsonLinesEventLog::close() {
  if (closed_) return;
  replaceAtomically(path_, [&](const std::filesystem::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out << lines_;
    out.close();
    if (!out) throw Error(fmt::format("Cannot write {}", path_.string()));
  });
  closed_ = true;
}

void MemoryEventLog::emit(double time, std::string_view scene, const SceneEvent& event) {
  checkSceneEvent(event);
  events_.push_back({time, std::string(scene), event});
}

}  // namespace vitrine::host
