#pragma once
// The arithmetic of handing frames over as DMA-BUFs, without PipeWire or Vulkan: which DRM format
// modifier to allocate with, given the driver's list and the consumer's, and whether an exported
// image's memory planes can be described to a consumer (PipeWire's spa_data and spa_chunk fields).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace vitrine::gpu::drm {

// DRM's modifier values (libdrm's fourcc header): a plain row-major layout, and "no explicit modifier".
inline constexpr uint64_t kLinear = 0;
inline constexpr uint64_t kInvalid = 0x00ffffffffffffffULL;

// A modifier the driver can export images of one format with, and how many memory planes it takes.
struct DriverModifier {
  uint64_t modifier = kLinear;
  uint32_t planes = 1;
  bool operator==(const DriverModifier&) const = default;
};

// The modifiers both sides accept, in the consumer's order of preference (its list is the negotiated
// choice), without kInvalid (an image needs an explicit layout to be described) and without repeats.
std::vector<uint64_t> acceptable(std::span<const DriverModifier> driver, std::span<const uint64_t> consumer);

// The modifier to fixate on when no test allocation tells otherwise: the consumer's first acceptable.
std::optional<uint64_t> choose(std::span<const DriverModifier> driver, std::span<const uint64_t> consumer);

// Planes the driver lists for `modifier`; 0 when it does not list it.
uint32_t planesOf(std::span<const DriverModifier> driver, uint64_t modifier);

// One memory plane of an exported image, as vkGetImageSubresourceLayout reports it.
struct Plane {
  uint64_t offset = 0;
  uint64_t size = 0;
  uint64_t rowPitch = 0;
};

// Why these planes cannot be handed over (empty: they can): the count must be the modifier's, every
// plane inside the memory, offsets within 32 bits and strides within a positive 32-bit int (spa_chunk),
// and a linear plane must hold `height` rows of `width * bytesPerPixel` bytes at its pitch.
std::string checkPlanes(std::span<const Plane> planes, uint32_t expectedPlanes, uint64_t modifier, uint32_t width,
                        uint32_t height, uint32_t bytesPerPixel, uint64_t memorySize);

// "linear", or the vendor and value ("nvidia 0x0300000000606015") for the console and the menu.
std::string describeModifier(uint64_t modifier);

}  // namespace vitrine::gpu::drm
