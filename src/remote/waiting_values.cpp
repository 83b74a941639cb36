#include "remote/waiting_values.h"

#include <algorithm>
#include <vector>

namespace vitrine::remote {

size_t WaitingValues::fromClient(const std::string& client) const {
  const auto it = clients_.find(client);
  return it == clients_.end() ? 0 : it->second;
}

void WaitingValues::release(const std::string& client) {
  if (const auto it = clients_.find(client); it != clients_.end() && --it->second == 0) clients_.erase(it);
}

bool WaitingValues::put(const std::string& client, const std::string& scene, const std::string& key,
                        const std::string& value) {
  const auto sceneIt = scenes_.find(scene);
  Entry* existing = nullptr;
  if (sceneIt != scenes_.end())
    if (const auto it = sceneIt->second.find(key); it != sceneIt->second.end()) existing = &it->second;
  if (existing) {
    if (existing->client != client) {
      if (fromClient(client) >= limits_.perClient) return false;
      release(existing->client);
      ++clients_[client];
      existing->client = client;
    }
    existing->value = value;
    return true;
  }
  if (size_ >= limits_.total || fromClient(client) >= limits_.perClient) return false;
  scenes_[scene][key] = Entry{value, client, arrivals_++};
  ++clients_[client];
  ++size_;
  return true;
}

params::KeyValues WaitingValues::take(std::string_view scene) {
  const auto it = scenes_.find(scene);
  if (it == scenes_.end()) return {};
  std::vector<std::pair<size_t, std::pair<std::string, std::string>>> ordered;
  for (auto& [key, entry] : it->second) {
    ordered.push_back({entry.order, {key, std::move(entry.value)}});
    release(entry.client);
    --size_;
  }
  scenes_.erase(it);
  std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  params::KeyValues values;
  for (auto& [order, kv] : ordered) values.push_back(std::move(kv));
  return values;
}

}  // namespace vitrine::remote
