#pragma once
// Failures a test can inject, to show what a user sees when the GPU goes away or runs out of memory,
// and a smaller device, to take the paths a smaller GPU takes (VITRINE_INJECT in the environment; read
// once):
//   device-lost:N     the Nth queue submission reports VK_ERROR_DEVICE_LOST
//   out-of-memory:N   the Nth device memory allocation reports VK_ERROR_OUT_OF_DEVICE_MEMORY
//   scene-start:NAME  scene NAME fails to start, every time (a kiosk skips it)
//   storage-range:B   the device reports at most B bytes of maxStorageBufferRange (noodles then binds
//                     its strands in chunks, as 10^7 segments need on a device with 128 MiB)
//   shm-bytes:B       the system grants shared-memory segments of at most B bytes (as a small
//                     kernel.shmmax would): a software device's window bigger than that is drawn
//                     through Vulkan's swapchain instead (host/present/shm_presenter.h)
//   dirty-memory:1    every device allocation the host can map starts filled with garbage (every byte
//                     0x3f: 0.75 in a float, 1.8 in a half float), as a GPU's recycled memory may, where
//                     lavapipe's starts zeroed: a frame that reads memory nothing wrote shows it
// Several are separated by commas. The two faults fire once per process, so a kiosk's restarted gallery
// runs on, as it would after a driver reset; the smaller device and the dirty memory hold throughout.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string_view>

namespace vitrine::gpu {

enum class Fault { DeviceLost, OutOfMemory };

// VK_SUCCESS, or the injected result when this call is the one that fails.
VkResult injectedFault(Fault fault);

// True when scene `name` is to fail as it starts.
bool injectedSceneFailure(std::string_view name);

// The storage-buffer range the device is to report instead of its own, when smaller.
std::optional<uint64_t> injectedStorageRange();

// The most bytes a shared-memory segment may have, when limited.
std::optional<uint64_t> injectedShmLimit();

// True when fresh device memory is to be filled with garbage.
bool injectedDirtyMemory();

}  // namespace vitrine::gpu
