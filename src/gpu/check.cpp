#include "gpu/check.h"

#include <fmt/format.h>

namespace vitrine::gpu {

const char* resultName(VkResult result) {
  switch (result) {
#define NAME(r) case r: return #r;
    NAME(VK_SUCCESS) NAME(VK_NOT_READY) NAME(VK_TIMEOUT) NAME(VK_INCOMPLETE)
    NAME(VK_ERROR_OUT_OF_HOST_MEMORY) NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    NAME(VK_ERROR_INITIALIZATION_FAILED) NAME(VK_ERROR_DEVICE_LOST) NAME(VK_ERROR_MEMORY_MAP_FAILED)
    NAME(VK_ERROR_LAYER_NOT_PRESENT) NAME(VK_ERROR_EXTENSION_NOT_PRESENT)
    NAME(VK_ERROR_FEATURE_NOT_PRESENT) NAME(VK_ERROR_INCOMPATIBLE_DRIVER)
    NAME(VK_ERROR_TOO_MANY_OBJECTS) NAME(VK_ERROR_FORMAT_NOT_SUPPORTED)
    NAME(VK_ERROR_SURFACE_LOST_KHR) NAME(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    NAME(VK_SUBOPTIMAL_KHR) NAME(VK_ERROR_OUT_OF_DATE_KHR)
#undef NAME
    default: return "VkResult(unknown)";
  }
}

void throwVkError(VkResult result, const char* call, const char* file, int line) {
  throw Error(fmt::format("Vulkan call failed with {} at {}:{}\n  {}", resultName(result), file, line, call));
}

}  // namespace vitrine::gpu
