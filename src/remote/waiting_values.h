#pragma once
// Values clients sent for a scene that is not showing, kept until it opens. Bounded, whatever clients
// send: one value per scene and key (a newer one replaces the older, whoever sent it), at most
// `perClient` of them from one client and `total` from all clients together; beyond that a value is
// refused (the caller counts it). Without this, a client setting values for another scene could grow
// the gallery's memory without end. Not thread-safe: the main thread owns it.
#include "params/schema.h"

#include <cstddef>
#include <map>
#include <string>
#include <string_view>

namespace vitrine::remote {

struct WaitingLimits {
  size_t perClient = 64;  // a phone setting every parameter of every scene stays well under this
  size_t total = 256;
};

class WaitingValues {
 public:
  explicit WaitingValues(WaitingLimits limits = {}) : limits_(limits) {}

  // False when it would go over a limit: nothing changes. Replacing a waiting value never fails (it
  // moves to `client`'s count, if that client has room).
  bool put(const std::string& client, const std::string& scene, const std::string& key, const std::string& value);
  // The values waiting for `scene`, in the order their keys first arrived; then forgotten.
  params::KeyValues take(std::string_view scene);
  size_t size() const { return size_; }
  size_t fromClient(const std::string& client) const;

 private:
  struct Entry {
    std::string value, client;
    size_t order = 0;
  };
  void release(const std::string& client);
  WaitingLimits limits_;
  std::map<std::string, std::map<std::string, Entry>, std::less<>> scenes_;
  std::map<std::string, size_t> clients_;  // values each client holds (only clients holding some)
  size_t size_ = 0, arrivals_ = 0;
};

}  // namespace vitrine::remote
