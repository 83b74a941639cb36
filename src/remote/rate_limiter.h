#pragma once
// Message budgets. A token bucket per client: `rate` messages a second on average, bursts up to
// `burst`; a message over budget is refused, not delayed, so a flooding client never queues work.
#include <chrono>
#include <cstddef>
#include <string>
#include <unordered_map>

namespace vitrine::remote {

using SteadyClock = std::chrono::steady_clock;

struct RateLimit {
  double rate = 120.0;   // messages per second, sustained (two 60 Hz streams)
  double burst = 240.0;  // messages at once after a quiet spell
};

class TokenBucket {
 public:
  explicit TokenBucket(RateLimit limit, SteadyClock::time_point now = SteadyClock::now())
      : limit_(limit), tokens_(limit.burst), last_(now) {}
  bool take(SteadyClock::time_point now = SteadyClock::now());
  SteadyClock::time_point lastSeen() const { return last_; }

 private:
  RateLimit limit_;
  double tokens_;
  SteadyClock::time_point last_;
};

// Buckets keyed by sender (OSC: the sender's IP address). The table holds at most `maxSenders`
// entries: a new sender beyond that evicts the one heard from longest ago, so a stream of spoofed
// source addresses cannot grow memory. Not thread-safe: one server thread owns it.
class SenderBudgets {
 public:
  explicit SenderBudgets(RateLimit limit, size_t maxSenders = 256) : limit_(limit), maxSenders_(maxSenders) {}
  bool take(const std::string& sender, SteadyClock::time_point now = SteadyClock::now());
  size_t size() const { return buckets_.size(); }

 private:
  RateLimit limit_;
  size_t maxSenders_;
  std::unordered_map<std::string, TokenBucket> buckets_;
};

}  // namespace vitrine::remote
