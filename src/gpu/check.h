#pragma once
// Vulkan error handling: every failing call becomes a vitrine::Error carrying the call, the result
// name and the source line. Stays on in Release: a silent failure on a user's GPU costs more than a branch.
#include <vulkan/vulkan.h>

#include "core/error.h"

namespace vitrine {
namespace gpu {
const char* resultName(VkResult result);
[[noreturn]] void throwVkError(VkResult result, const char* call, const char* file, int line);
}  // namespace gpu
}  // namespace vitrine

#define VK_CHECK(call)                                                              \
  do {                                                                              \
    const VkResult vk_check_result_ = (call);                                       \
    if (vk_check_result_ < 0)                                                       \
      ::vitrine::gpu::throwVkError(vk_check_result_, #call, __FILE__, __LINE__);    \
  } while (0)
