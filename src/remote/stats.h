#pragma once
// Counters of what remote clients sent and what became of it, written by the server threads and read
// by the host and tests. Every message lands in exactly one of them, so a test or a status line can
// tell "ignored because malformed" from "ignored because too fast".
#include <atomic>
#include <cstdint>

namespace vitrine::remote {

struct RemoteStatsSnapshot {
  uint64_t accepted = 0;      // parsed, checked and queued for the main thread
  uint64_t malformed = 0;     // not a message at all: bad JSON or OSC, wrong argument types, unknown "type"
  uint64_t refused = 0;       // well-formed but unknown scene/parameter/action, or a value out of range
  uint64_t rateLimited = 0;   // over the client's message budget
  uint64_t oversized = 0;     // a datagram, WebSocket message or HTTP request over its size limit
  uint64_t unauthorised = 0;  // a request or socket without the right token
  uint64_t dropped = 0;       // accepted but the inbox was full (the main thread is not draining)
  uint64_t connectionsRefused = 0;  // over the client limit
};

class RemoteStats {
 public:
  std::atomic<uint64_t> accepted{0}, malformed{0}, refused{0}, rateLimited{0}, oversized{0},
      unauthorised{0}, dropped{0}, connectionsRefused{0};

  RemoteStatsSnapshot snapshot() const {
    const auto load = [](const std::atomic<uint64_t>& counter) { return counter.load(std::memory_order_relaxed); };
    return {load(accepted), load(malformed),    load(refused), load(rateLimited),
            load(oversized), load(unauthorised), load(dropped), load(connectionsRefused)};
  }
};

inline void count(std::atomic<uint64_t>& counter) { counter.fetch_add(1, std::memory_order_relaxed); }

}  // namespace vitrine::remote
