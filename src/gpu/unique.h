#pragma once
// Move-only ownership of Vulkan device-level handles. Every object a scene or the host creates is
// held by one of these, so nothing outside this header calls vkDestroy*.
#include "gpu/memory_ledger.h"

#include <vulkan/vulkan.h>

#include <utility>

namespace vitrine::gpu {

template <typename T> struct Destroyer;
#define VITRINE_DESTROYER(Type, fn)                                                   \
  template <> struct Destroyer<Type> {                                               \
    static void destroy(VkDevice device, Type handle) { fn(device, handle, nullptr); } \
  };
VITRINE_DESTROYER(VkBuffer, vkDestroyBuffer)
VITRINE_DESTROYER(VkImage, vkDestroyImage)
VITRINE_DESTROYER(VkImageView, vkDestroyImageView)
VITRINE_DESTROYER(VkSampler, vkDestroySampler)
VITRINE_DESTROYER(VkPipeline, vkDestroyPipeline)
VITRINE_DESTROYER(VkPipelineLayout, vkDestroyPipelineLayout)
VITRINE_DESTROYER(VkDescriptorSetLayout, vkDestroyDescriptorSetLayout)
VITRINE_DESTROYER(VkDescriptorPool, vkDestroyDescriptorPool)
VITRINE_DESTROYER(VkShaderModule, vkDestroyShaderModule)
VITRINE_DESTROYER(VkCommandPool, vkDestroyCommandPool)
VITRINE_DESTROYER(VkFence, vkDestroyFence)
VITRINE_DESTROYER(VkSemaphore, vkDestroySemaphore)
VITRINE_DESTROYER(VkQueryPool, vkDestroyQueryPool)
VITRINE_DESTROYER(VkRenderPass, vkDestroyRenderPass)
VITRINE_DESTROYER(VkFramebuffer, vkDestroyFramebuffer)
VITRINE_DESTROYER(VkSwapchainKHR, vkDestroySwapchainKHR)
#undef VITRINE_DESTROYER
template <> struct Destroyer<VkDeviceMemory> {
  static void destroy(VkDevice device, VkDeviceMemory memory) {
    noteFreed(memory);
    vkFreeMemory(device, memory, nullptr);
  }
};

template <typename T>
class Unique {
 public:
  Unique() = default;
  Unique(VkDevice device, T handle) : device_(device), handle_(handle) {}
  Unique(Unique&& other) noexcept
      : device_(other.device_), handle_(std::exchange(other.handle_, VK_NULL_HANDLE)) {}
  Unique& operator=(Unique&& other) noexcept {
    if (this != &other) {
      reset();
      device_ = other.device_;
      handle_ = std::exchange(other.handle_, VK_NULL_HANDLE);
    }
    return *this;
  }
  Unique(const Unique&) = delete;
  Unique& operator=(const Unique&) = delete;
  ~Unique() { reset(); }

  void reset() {
    if (handle_ != VK_NULL_HANDLE) Destroyer<T>::destroy(device_, handle_);
    handle_ = VK_NULL_HANDLE;
  }
  T get() const { return handle_; }
  operator T() const { return handle_; }  // NOLINT: handles pass straight into Vulkan calls
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  T handle_ = VK_NULL_HANDLE;
};

}  // namespace vitrine::gpu
