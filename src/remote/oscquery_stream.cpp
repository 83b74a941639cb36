#include "remote/oscquery_stream.h"

namespace vitrine::remote {

bool ValueStream::listen(std::string_view path) {
  if (paths_.contains(path)) return true;
  if (paths_.size() >= limits_.maxPaths) return false;
  paths_.emplace(path);
  return true;
}

void ValueStream::ignore(std::string_view path) {
  if (const auto it = paths_.find(path); it != paths_.end()) paths_.erase(it);
  if (const auto it = waiting_.find(path); it != waiting_.end()) waiting_.erase(it);
}

void ValueStream::changed(std::string_view path) {
  if (paths_.contains(path)) waiting_.emplace(path);
}

std::vector<std::string> ValueStream::due(Clock::time_point now) {
  if (waiting_.empty() || (lastSent_ && now < *lastSent_ + limits_.interval)) return {};
  lastSent_ = now;
  std::vector<std::string> paths(waiting_.begin(), waiting_.end());
  waiting_.clear();
  return paths;
}

std::optional<ValueStream::Clock::time_point> ValueStream::next() const {
  if (waiting_.empty()) return std::nullopt;
  return lastSent_ ? *lastSent_ + limits_.interval : Clock::now();
}

}  // namespace vitrine::remote
