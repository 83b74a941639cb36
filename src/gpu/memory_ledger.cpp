#include "gpu/memory_ledger.h"

#include <mutex>
#include <unordered_map>

namespace vitrine::gpu {
namespace {

struct Ledger {
  std::mutex mutex;
  std::unordered_map<VkDeviceMemory, VkDeviceSize> sizes;
  MemoryTally live;
};

Ledger& ledger() {
  static Ledger instance;
  return instance;
}

}  // namespace

void noteAllocated(VkDeviceMemory memory, VkDeviceSize bytes) {
  Ledger& l = ledger();
  const std::lock_guard lock(l.mutex);
  l.sizes[memory] = bytes;
  l.live.allocations += 1;
  l.live.bytes += bytes;
}

void noteFreed(VkDeviceMemory memory) {
  Ledger& l = ledger();
  const std::lock_guard lock(l.mutex);
  const auto it = l.sizes.find(memory);
  if (it == l.sizes.end()) return;
  l.live.allocations -= 1;
  l.live.bytes -= it->second;
  l.sizes.erase(it);
}

MemoryTally liveDeviceMemory() {
  Ledger& l = ledger();
  const std::lock_guard lock(l.mutex);
  return l.live;
}

}  // namespace vitrine::gpu
