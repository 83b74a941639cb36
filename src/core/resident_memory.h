#pragma once
// The process's resident memory (VmRSS), which on a CPU device like lavapipe also holds every Vulkan
// allocation: what the soak watches, sampled by frames so that a fast GPU's short run is measured too.
#include <cstdint>
#include <optional>

namespace vitrine {

// Bytes resident now; none where /proc/self/status cannot tell (not Linux).
std::optional<uint64_t> residentBytes();

}  // namespace vitrine
