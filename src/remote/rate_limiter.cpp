#include "remote/rate_limiter.h"

#include <algorithm>

namespace vitrine::remote {

bool TokenBucket::take(SteadyClock::time_point now) {
  if (now > last_) {
    const double seconds = std::chrono::duration<double>(now - last_).count();
    tokens_ = std::min(limit_.burst, tokens_ + seconds * limit_.rate);
    last_ = now;
  }
  if (tokens_ < 1.0) return false;
  tokens_ -= 1.0;
  return true;
}

bool SenderBudgets::take(const std::string& sender, SteadyClock::time_point now) {
  auto found = buckets_.find(sender);
  if (found == buckets_.end()) {
    if (buckets_.size() >= maxSenders_) {
      const auto oldest = std::min_element(buckets_.begin(), buckets_.end(), [](const auto& a, const auto& b) {
        return a.second.lastSeen() < b.second.lastSeen();
      });
      buckets_.erase(oldest);
    }
    found = buckets_.emplace(sender, TokenBucket(limit_, now)).first;
  }
  return found->second.take(now);
}

}  // namespace vitrine::remote
