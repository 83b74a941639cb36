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
  // The two a user can meet on a working install get a sentence that says what to do.
  if (result == VK_ERROR_DEVICE_LOST)
    throw Error(fmt::format("The GPU stopped responding (VK_ERROR_DEVICE_LOST: its driver reset it or it crashed). "
                            "Start Vitrine again; if it happens again, a smaller --size or lower quality settings "
                            "ask less of it.\n  at {}:{}: {}", file, line, call));
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw Error(fmt::format("Out of {} memory ({}). A smaller --size or lower quality settings (fewer strands, "
                            "chains or samples) need less; other programs on the GPU may be holding it.\n  at {}:{}: {}",
                            result == VK_ERROR_OUT_OF_DEVICE_MEMORY ? "GPU" : "host", resultName(result), file, line,
                            call));
  throw Error(fmt::format("Vulkan call failed with {} at {}:{}\n  {}", resultName(result), file, line, call));
}

}  // namespace vitrine::gpu
