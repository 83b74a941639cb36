#pragma once
// One OSCQuery WebSocket's LISTEN set and the values waiting to be streamed to it. A value that
// changes faster than `interval` is coalesced: the client gets its latest value, at most once per
// interval for all its paths together, so a fast-moving value never floods the socket. Bounded: at
// most `maxPaths` paths listened to, and the waiting set is a subset of them. Not thread-safe: the web
// server's I/O thread owns it.
#include <chrono>
#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::remote {

struct StreamLimits {
  size_t maxPaths = 512;                        // more than every parameter of every scene
  std::chrono::milliseconds interval{1000 / 30};  // at most 30 sends a second per socket
};

class ValueStream {
 public:
  using Clock = std::chrono::steady_clock;
  explicit ValueStream(StreamLimits limits = {}) : limits_(limits) {}

  // False when the set is full (the path is not added). Listening twice is one listen.
  bool listen(std::string_view path);
  void ignore(std::string_view path);  // also drops a value waiting for it
  bool listening(std::string_view path) const { return paths_.contains(std::string(path)); }
  size_t size() const { return paths_.size(); }

  // A value changed: waits to be sent if the client listens to it.
  void changed(std::string_view path);
  // The paths to send now (their latest values are read at send time), or nothing yet; then `next()`
  // says when to ask again.
  std::vector<std::string> due(Clock::time_point now = Clock::now());
  std::optional<Clock::time_point> next() const;

 private:
  StreamLimits limits_;
  std::set<std::string, std::less<>> paths_, waiting_;
  std::optional<Clock::time_point> lastSent_;
};

}  // namespace vitrine::remote
