#include "gpu/fault_injection.h"

#include <atomic>
#include <charconv>
#include <cstdlib>
#include <string>
#include <string_view>

namespace vitrine::gpu {
namespace {

struct Plan {
  uint64_t at[2] = {0, 0};  // per Fault: the call that fails, 1-based; 0 never
  std::string failingScene;
  uint64_t storageRange = 0;  // 0: the device's own
  uint64_t shmLimit = 0;      // 0: the system's own
  bool dirtyMemory = false;
};

Plan readPlan() {
  Plan plan;
  const char* text = std::getenv("VITRINE_INJECT");
  for (std::string_view rest = text ? text : ""; !rest.empty();) {
    const size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    const size_t colon = item.find(':');
    if (colon == std::string_view::npos) continue;
    uint64_t n = 0;
    const std::string_view number = item.substr(colon + 1);
    std::from_chars(number.data(), number.data() + number.size(), n);
    if (item.substr(0, colon) == "device-lost") plan.at[int(Fault::DeviceLost)] = n;
    if (item.substr(0, colon) == "out-of-memory") plan.at[int(Fault::OutOfMemory)] = n;
    if (item.substr(0, colon) == "scene-start") plan.failingScene = item.substr(colon + 1);
    if (item.substr(0, colon) == "storage-range") plan.storageRange = n;
    if (item.substr(0, colon) == "shm-bytes") plan.shmLimit = n;
    if (item.substr(0, colon) == "dirty-memory") plan.dirtyMemory = n != 0;
  }
  return plan;
}

const Plan& plan() {
  static const Plan read = readPlan();
  return read;
}

std::optional<uint64_t> limit(uint64_t bytes) { return bytes == 0 ? std::nullopt : std::optional(bytes); }

}  // namespace

bool injectedSceneFailure(std::string_view name) { return !plan().failingScene.empty() && plan().failingScene == name; }

std::optional<uint64_t> injectedStorageRange() { return limit(plan().storageRange); }

std::optional<uint64_t> injectedShmLimit() { return limit(plan().shmLimit); }

bool injectedDirtyMemory() { return plan().dirtyMemory; }

VkResult injectedFault(Fault fault) {
  static std::atomic<uint64_t> calls[2];
  const uint64_t at = plan().at[int(fault)];
  if (at == 0 || calls[int(fault)].fetch_add(1) + 1 != at) return VK_SUCCESS;
  return fault == Fault::DeviceLost ? VK_ERROR_DEVICE_LOST : VK_ERROR_OUT_OF_DEVICE_MEMORY;
}

}  // namespace vitrine::gpu
