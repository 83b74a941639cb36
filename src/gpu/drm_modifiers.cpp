#include "gpu/drm_modifiers.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

namespace vitrine::gpu::drm {

std::vector<uint64_t> acceptable(std::span<const DriverModifier> driver, std::span<const uint64_t> consumer) {
  std::vector<uint64_t> both;
  for (const uint64_t modifier : consumer) {
    if (modifier == kInvalid || std::find(both.begin(), both.end(), modifier) != both.end()) continue;
    if (planesOf(driver, modifier) > 0) both.push_back(modifier);
  }
  return both;
}

std::optional<uint64_t> choose(std::span<const DriverModifier> driver, std::span<const uint64_t> consumer) {
  const auto both = acceptable(driver, consumer);
  if (both.empty()) return std::nullopt;
  return both.front();
}

uint32_t planesOf(std::span<const DriverModifier> driver, uint64_t modifier) {
  for (const DriverModifier& entry : driver)
    if (entry.modifier == modifier) return entry.planes;
  return 0;
}

std::string checkPlanes(std::span<const Plane> planes, uint32_t expectedPlanes, uint64_t modifier, uint32_t width,
                        uint32_t height, uint32_t bytesPerPixel, uint64_t memorySize) {
  if (planes.empty() || planes.size() > 4) return fmt::format("{} memory planes (1 to 4 can be described)", planes.size());
  if (planes.size() != expectedPlanes)
    return fmt::format("{} memory planes where the modifier has {}", planes.size(), expectedPlanes);
  constexpr uint64_t kMaxOffset = std::numeric_limits<uint32_t>::max();
  constexpr uint64_t kMaxStride = uint64_t(std::numeric_limits<int32_t>::max());
  for (size_t i = 0; i < planes.size(); ++i) {
    const Plane& plane = planes[i];
    if (plane.rowPitch == 0 || plane.rowPitch > kMaxStride)
      return fmt::format("plane {}: a row pitch of {} bytes", i, plane.rowPitch);
    if (plane.offset > kMaxOffset) return fmt::format("plane {}: an offset of {} bytes", i, plane.offset);
    if (plane.offset > memorySize || plane.size > memorySize - plane.offset)
      return fmt::format("plane {}: {} bytes at {} outside the memory's {}", i, plane.size, plane.offset, memorySize);
  }
  if (modifier == kLinear) {
    const Plane& plane = planes.front();
    const uint64_t row = uint64_t(width) * bytesPerPixel;
    if (plane.rowPitch < row) return fmt::format("a row pitch of {} bytes for rows of {}", plane.rowPitch, row);
    const uint64_t needed = height == 0 ? 0 : plane.rowPitch * (height - 1) + row;
    if (needed > plane.size) return fmt::format("{} rows need {} bytes, the plane has {}", height, needed, plane.size);
  }
  return {};
}

std::string describeModifier(uint64_t modifier) {
  if (modifier == kLinear) return "linear";
  if (modifier == kInvalid) return "implicit";
  static constexpr const char* kVendors[] = {"none", "intel", "amd", "nvidia", "samsung", "qcom", "vivante",
                                             "broadcom", "arm", "allwinner", "amlogic"};
  const uint64_t vendor = modifier >> 56;
  const char* name = vendor < std::size(kVendors) ? kVendors[vendor] : "vendor";
  return fmt::format("{} {:#018x}", name, modifier);
}

}  // namespace vitrine::gpu::drm
