#pragma once
// The Vulkan instance, the chosen physical device, the logical device and its one universal queue.
// Validation, when on, routes every warning or error through one counter, so a test can fail on it.
#include "gpu/graveyard.h"
#include "gpu/unique.h"

#include <array>
#include <atomic>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace vitrine::gpu {

struct InstanceOptions {
  bool validation = false;                     // VK_LAYER_KHRONOS_validation + synchronisation checks
  std::vector<const char*> extensions;         // e.g. what GLFW needs for a surface
};

class Instance {
 public:
  explicit Instance(const InstanceOptions& options);
  ~Instance();
  Instance(const Instance&) = delete;
  Instance& operator=(const Instance&) = delete;

  VkInstance handle() const { return instance_; }
  bool validation() const { return validation_; }
  bool debugUtils() const { return debugUtils_; }
  // Validation warnings and errors seen so far (also printed to stderr as they arrive).
  int validationMessages() const { return messages_.load(); }

  struct Adapter {
    VkPhysicalDevice handle;
    VkPhysicalDeviceProperties properties;
    bool suitable;       // Vulkan 1.3 with dynamic rendering, synchronization2 and push descriptors
    std::string reason;  // why not, when it is not
  };
  std::vector<Adapter> adapters() const;

 private:
  static VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                       VkDebugUtilsMessageTypeFlagsEXT types,
                                       const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  bool validation_ = false;
  bool debugUtils_ = false;
  std::atomic<int> messages_{0};
};

struct DeviceOptions {
  std::string selector;                  // "--device": an index or a name substring; empty: best
  VkSurfaceKHR surface = VK_NULL_HANDLE; // when set, the queue must present to it and swapchains load
  bool pipelineStatistics = false;       // capture each pipeline's compiler statistics and count each pass's
                                         // shader invocations, where the device can
};

class Device {
 public:
  Device(const Instance& instance, const DeviceOptions& options);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  VkDevice handle() const { return device_; }
  operator VkDevice() const { return device_; }  // NOLINT
  VkPhysicalDevice physical() const { return physical_; }
  VkInstance instance() const { return instance_.handle(); }
  const Instance& owner() const { return instance_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const VkPhysicalDeviceLimits& limits() const { return properties_.limits; }
  std::string describe() const;  // "NVIDIA H100 (driver 0x..., Vulkan 1.3.x)"
  // Storage images without a format qualifier: lets one compute pass write any output format.
  bool storageWriteWithoutFormat() const { return storageWriteWithoutFormat_; }
  // 64-bit integers in shaders and atomics on them in storage buffers (noodles' visibility buffer).
  bool bufferInt64Atomics() const { return bufferInt64Atomics_; }
  // Pipelines are built with their compiler statistics captured (DeviceOptions::pipelineStatistics,
  // on a device with VK_KHR_pipeline_executable_properties): pipelineStatistics reads them back.
  bool capturesPipelineStatistics() const { return getExecutableStatistics_ != nullptr; }
  // "stage: name value, ..." per executable of `pipeline` (registers, spills, instructions: whatever
  // the driver reports); empty when statistics are not captured.
  std::vector<std::string> pipelineStatistics(VkPipeline pipeline) const;
  // Pipeline-statistics queries are enabled (DeviceOptions::pipelineStatistics, on a device with the
  // pipelineStatisticsQuery feature): the pass timer counts each pass's shader invocations.
  bool countsInvocations() const { return countsInvocations_; }
  // What bounds one large allocation (noodles' strands): the largest buffer the device makes (the
  // smaller of maintenance4's maxBufferSize and maintenance3's maxMemoryAllocationSize) and the
  // size of its largest device-local heap.
  struct MemoryLimits {
    VkDeviceSize maxBufferSize = 0;
    VkDeviceSize largestDeviceLocalHeap = 0;
  };
  const MemoryLimits& memoryLimits() const { return memoryLimits_; }
  // What optimally tiled images of `format` support (storage, linear filtering, ...): a scene that
  // needs more than the formats every device offers checks here.
  VkFormatFeatureFlags optimalTilingFeatures(VkFormat format) const;

  Unique<VkDeviceMemory> allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags wanted,
                                  VkMemoryPropertyFlags fallback = 0, const void* next = nullptr) const;

  // Images exported as DMA-BUFs with an explicit DRM format modifier (gpu/dmabuf_export.h): the device
  // offered VK_KHR_external_memory_fd, VK_EXT_external_memory_dma_buf and VK_EXT_image_drm_format_modifier,
  // and they are enabled. The entry points below are loaded only then.
  bool exportsDmaBuf() const { return exportsDmaBuf_; }
  PFN_vkGetMemoryFdKHR getMemoryFd = nullptr;
  PFN_vkGetMemoryFdPropertiesKHR getMemoryFdProperties = nullptr;
  PFN_vkGetImageDrmFormatModifierPropertiesEXT getImageDrmFormatModifierProperties = nullptr;

  // The one place work reaches the queue. Every submission signals the next value of the device's
  // timeline semaphore and returns it: its serial. Binary semaphores (swapchain) and a fence are optional.
  struct Submit {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    std::span<const VkSemaphoreSubmitInfo> wait;
    std::span<const VkSemaphoreSubmitInfo> signal;  // at most kMaxSignals, besides the timeline
  };
  static constexpr size_t kMaxSignals = 8;  // the window and up to seven more outputs
  uint64_t submit(const Submit& work) const;
  uint64_t lastSubmitted() const { return submitted_; }
  uint64_t completed() const;            // the newest serial the GPU has finished
  void wait(uint64_t serial) const;      // blocks until that submission has finished
  void waitIdle() const;                 // every submission so far; exit and tests only

  // Records and runs a one-off command buffer, waiting for it: set-up uploads and read-backs only.
  // The command buffer is freed also when `record` throws.
  void submitNow(const std::function<void(VkCommandBuffer)>& record) const;

  // Deferred destruction: `object` is destroyed once every submission made so far, and the one being
  // recorded now, has finished. Host and scenes hand over what frames in flight may still use.
  template <typename T> void retire(T&& object) const { graveyard_.bury(std::forward<T>(object), submitted_ + 1); }
  void collectRetired() const { graveyard_.collect(completed()); }  // once a frame
  void drainRetired() const;  // waits for the queue, then destroys everything retired (shutdown)
  size_t retiredCount() const { return graveyard_.size(); }

  // Stock samplers, made once: what the host offers instead of scenes creating their own.
  enum class Filter { Nearest, Linear };
  enum class Address { Clamp, Repeat };
  VkSampler sampler(Filter filter, Address address, bool mipmaps = false) const;

  // Debug-utils names and labels; no-ops when the extension is missing.
  void name(VkObjectType type, uint64_t handle, const std::string& name) const;
  template <typename T> void name(T handle, VkObjectType type, const std::string& label) const {
    name(type, reinterpret_cast<uint64_t>(handle), label);
  }
  void beginLabel(VkCommandBuffer cmd, const char* label) const;
  void endLabel(VkCommandBuffer cmd) const;

  PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;

 private:
  void dirty(VkDeviceMemory memory, uint32_t type, VkDeviceSize size) const;
  // Loaded only when the device captures pipeline statistics.
  PFN_vkGetPipelineExecutablePropertiesKHR getExecutableProperties_ = nullptr;
  PFN_vkGetPipelineExecutableStatisticsKHR getExecutableStatistics_ = nullptr;
  const Instance& instance_;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  bool storageWriteWithoutFormat_ = false;
  bool bufferInt64Atomics_ = false;
  bool countsInvocations_ = false;
  bool exportsDmaBuf_ = false;
  MemoryLimits memoryLimits_;
  Unique<VkCommandPool> oneShotPool_;
  Unique<VkSemaphore> timeline_;
  mutable uint64_t submitted_ = 0;
  mutable Graveyard graveyard_;
  std::array<Unique<VkSampler>, 8> samplers_;
  PFN_vkSetDebugUtilsObjectNameEXT setName_ = nullptr;
  PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel_ = nullptr;
  PFN_vkCmdEndDebugUtilsLabelEXT endLabel_ = nullptr;
};

// "--list-devices": one line per adapter, marking the one that would be chosen.
std::string listDevices(const Instance& instance);

}  // namespace vitrine::gpu
