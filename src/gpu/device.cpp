#include "gpu/device.h"

#include <fmt/format.h>

#if defined(VITRINE_SANITIZE)
#include <dlfcn.h>
#endif

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "gpu/check.h"
#include "gpu/fault_injection.h"
#include "gpu/sync_objects.h"

namespace vitrine::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kNoDriver =
    "No Vulkan device found: install a Vulkan driver (on Debian 12: apt-get install mesa-vulkan-drivers "
    "for the lavapipe CPU renderer, or your GPU vendor's driver) and check with vulkaninfo --summary.";

bool hasExtension(const std::vector<VkExtensionProperties>& list, const char* name) {
  return std::any_of(list.begin(), list.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

std::vector<VkExtensionProperties> deviceExtensions(VkPhysicalDevice device) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> list(count);
  vkEnumerateDeviceExtensionProperties(device, nullptr, &count, list.data());
  return list;
}

// The first queue family that does graphics and compute, writes timestamps and (if asked) presents.
int universalFamily(VkPhysicalDevice device, VkSurfaceKHR surface) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  for (uint32_t i = 0; i < count; ++i) {
    const auto flags = families[i].queueFlags;
    if (!(flags & VK_QUEUE_GRAPHICS_BIT) || !(flags & VK_QUEUE_COMPUTE_BIT)) continue;
    if (families[i].timestampValidBits == 0) continue;
    if (surface) {
      VkBool32 present = VK_FALSE;
      vkGetPhysicalDeviceSurfaceSupportKHR(device, i, surface, &present);
      if (!present) continue;
    }
    return static_cast<int>(i);
  }
  return -1;
}

std::string whyUnsuitable(VkPhysicalDevice device, const VkPhysicalDeviceProperties& props, VkSurfaceKHR surface) {
  if (props.apiVersion < VK_API_VERSION_1_3) return "needs Vulkan 1.3";
  VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f13};
  vkGetPhysicalDeviceFeatures2(device, &f2);
  if (!f13.dynamicRendering || !f13.synchronization2) return "no dynamic rendering or synchronization2";
  const auto extensions = deviceExtensions(device);
  if (!hasExtension(extensions, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME)) return "no VK_KHR_push_descriptor";
  if (surface && !hasExtension(extensions, VK_KHR_SWAPCHAIN_EXTENSION_NAME)) return "no VK_KHR_swapchain";
  if (universalFamily(device, surface) < 0) return "no graphics+compute queue with timestamps";
  return {};
}

int typeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    default:
      return 3;
  }
}

const char* typeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    default:
      return "other";
  }
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// Index of the adapter to use: the selector's, else the best suitable one by type.
size_t choose(const std::vector<Instance::Adapter>& adapters, const std::string& selector) {
  if (adapters.empty()) throw Error(kNoDriver);
  if (!selector.empty()) {
    const bool numeric = std::all_of(selector.begin(), selector.end(), ::isdigit);
    for (size_t i = 0; i < adapters.size(); ++i) {
      const bool match = numeric ? std::to_string(i) == selector
                                 : lower(adapters[i].properties.deviceName).find(lower(selector)) != std::string::npos;
      if (!match) continue;
      if (!adapters[i].suitable)
        throw Error(fmt::format("Device {} ({}) cannot run Vitrine: {}.", i, adapters[i].properties.deviceName,
                                adapters[i].reason));
      return i;
    }
    throw Error(fmt::format("No Vulkan device matches --device '{}'; vitrine --list-devices shows them.", selector));
  }
  size_t best = adapters.size();
  for (size_t i = 0; i < adapters.size(); ++i) {
    if (!adapters[i].suitable) continue;
    if (best == adapters.size() ||
        typeRank(adapters[i].properties.deviceType) < typeRank(adapters[best].properties.deviceType))
      best = i;
  }
  if (best == adapters.size())
    throw Error(
        fmt::format("No Vulkan device can run Vitrine ({}: {}); Vitrine needs Vulkan 1.3 with dynamic "
                    "rendering — update the driver (Debian 12: apt-get install mesa-vulkan-drivers).",
                    adapters[0].properties.deviceName, adapters[0].reason));
  return best;
}

}  // namespace

// ---------------------------------------------------------------------------------------------- Instance

Instance::Instance(const InstanceOptions& options) {
  uint32_t count = 0;
  vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> available(count);
  vkEnumerateInstanceExtensionProperties(nullptr, &count, available.data());

  std::vector<const char*> extensions = options.extensions;
  debugUtils_ = hasExtension(available, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (debugUtils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

  std::vector<const char*> layers;
  validation_ = options.validation;
  if (validation_) {
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> installed(count);
    vkEnumerateInstanceLayerProperties(&count, installed.data());
    const bool found = std::any_of(installed.begin(), installed.end(), [](const VkLayerProperties& l) {
      return std::strcmp(l.layerName, kValidationLayer) == 0;
    });
    if (!found)
      throw Error(
          "Validation was asked for but VK_LAYER_KHRONOS_validation is not installed: "
          "apt-get install vulkan-validationlayers.");
    layers.push_back(kValidationLayer);
  }

  const VkApplicationInfo app{
      VK_STRUCTURE_TYPE_APPLICATION_INFO, nullptr,           "Vitrine", VK_MAKE_VERSION(0, 1, 0), "Vitrine",
      VK_MAKE_VERSION(0, 1, 0),           VK_API_VERSION_1_3};
  // Synchronisation validation catches hazards that leave the picture unchanged.
  const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  const VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, nullptr, 1, enables, 0, nullptr};
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.pNext = validation_ ? &features : nullptr;
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &Instance::onMessage;
  messengerInfo.pUserData = this;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = debugUtils_ ? &messengerInfo : (validation_ ? static_cast<const void*>(&features) : nullptr);
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  const VkResult result = vkCreateInstance(&info, nullptr, &instance_);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER) throw Error(kNoDriver);
  VK_CHECK(result);
#if defined(VITRINE_SANITIZE)
  // LeakSanitizer looks at exit, after the loader has unloaded the validation layer, so what the layer's
  // globals still held shows up as leaks from an unnamed module that no suppression can name. Kept
  // mapped, the layer is named, and tests/sanitize/lsan.supp can suppress it alone.
  if (validation_) dlopen("libVkLayer_khronos_validation.so", RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
  // Likewise the driver: lavapipe (and the LLVM it JIT-compiles shaders with) when it is the one loaded.
  dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
#endif

  if (debugUtils_) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    messengerInfo.pNext = nullptr;
    VK_CHECK(create(instance_, &messengerInfo, nullptr, &messenger_));
  }
}

Instance::~Instance() {
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
  }
  vkDestroyInstance(instance_, nullptr);
}

VkBool32 VKAPI_CALL Instance::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                        VkDebugUtilsMessageTypeFlagsEXT types,
                                        const VkDebugUtilsMessengerCallbackDataEXT* data, void* self) {
  // Loader chatter (GENERAL) is printed but does not fail a run; validation and performance do.
  const bool counts =
      types & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT);
  if (counts) static_cast<Instance*>(self)->messages_.fetch_add(1);
  std::fprintf(stderr, "[vulkan %s] %s\n",
               severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning", data->pMessage);
  return VK_FALSE;
}

std::vector<Instance::Adapter> Instance::adapters() const {
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance_, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance_, &count, devices.data());
  std::vector<Adapter> result;
  for (VkPhysicalDevice device : devices) {
    Adapter adapter{device, {}, false, {}};
    vkGetPhysicalDeviceProperties(device, &adapter.properties);
    adapter.reason = whyUnsuitable(device, adapter.properties, VK_NULL_HANDLE);
    adapter.suitable = adapter.reason.empty();
    result.push_back(adapter);
  }
  return result;
}

std::string listDevices(const Instance& instance) {
  const auto adapters = instance.adapters();
  if (adapters.empty()) throw Error(kNoDriver);
  size_t chosen = adapters.size();
  try {
    chosen = choose(adapters, {});
  } catch (const Error&) {
  }
  std::string out;
  for (size_t i = 0; i < adapters.size(); ++i) {
    const auto& p = adapters[i].properties;
    out += fmt::format("{} {} [{}] Vulkan {}.{}.{}{}{}\n", i == chosen ? '*' : ' ', i, typeName(p.deviceType),
                       VK_API_VERSION_MAJOR(p.apiVersion), VK_API_VERSION_MINOR(p.apiVersion),
                       VK_API_VERSION_PATCH(p.apiVersion), std::string("  ") + p.deviceName,
                       adapters[i].suitable ? "" : "  (unsuitable: " + adapters[i].reason + ")");
  }
  return out;
}

// ------------------------------------------------------------------------------------------------ Device

namespace {
size_t samplerIndex(Device::Filter filter, Device::Address address, bool mipmaps) {
  return size_t(filter) * 4 + size_t(address) * 2 + (mipmaps ? 1 : 0);
}

Device::MemoryLimits memoryLimitsOf(VkPhysicalDevice physical, const VkPhysicalDeviceMemoryProperties& memory) {
  VkPhysicalDeviceMaintenance4Properties maintenance4{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_PROPERTIES};
  VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES,
                                                      &maintenance4};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &maintenance3};
  vkGetPhysicalDeviceProperties2(physical, &properties);
  Device::MemoryLimits limits;
  limits.maxBufferSize = std::min(maintenance3.maxMemoryAllocationSize, maintenance4.maxBufferSize);
  for (uint32_t i = 0; i < memory.memoryHeapCount; ++i)
    if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
      limits.largestDeviceLocalHeap = std::max(limits.largestDeviceLocalHeap, memory.memoryHeaps[i].size);
  return limits;
}
}  // namespace

Device::Device(const Instance& instance, const DeviceOptions& options) : instance_(instance) {
  auto adapters = instance.adapters();
  if (options.surface)  // presenting narrows what is suitable
    for (auto& a : adapters) {
      a.reason = whyUnsuitable(a.handle, a.properties, options.surface);
      a.suitable = a.reason.empty();
    }
  const auto& adapter = adapters[choose(adapters, options.selector)];
  physical_ = adapter.handle;
  properties_ = adapter.properties;
  if (auto range = injectedStorageRange())  // a test taking a smaller device's paths (fault_injection.h)
    properties_.limits.maxStorageBufferRange = uint32_t(std::min<uint64_t>(*range, properties_.limits.maxStorageBufferRange));
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  memoryLimits_ = memoryLimitsOf(physical_, memory_);
  queueFamily_ = static_cast<uint32_t>(universalFamily(physical_, options.surface));

  // Required: dynamic rendering and synchronization2. Everything else is enabled when present.
  VkPhysicalDeviceVulkan13Features has13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceVulkan12Features has12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &has13};
  VkPhysicalDeviceVulkan11Features has11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &has12};
  VkPhysicalDeviceFeatures2 has{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &has11};
  vkGetPhysicalDeviceFeatures2(physical_, &has);

  VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  f13.dynamicRendering = VK_TRUE;
  f13.synchronization2 = VK_TRUE;
  f13.maintenance4 = has13.maintenance4;
  VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &f13};
  f12.timelineSemaphore = VK_TRUE;  // core in 1.2 and required by 1.3: the queue's serials
  f12.hostQueryReset = has12.hostQueryReset;
  f12.shaderFloat16 = has12.shaderFloat16;
  f12.scalarBlockLayout = has12.scalarBlockLayout;
  f12.storageBuffer8BitAccess = has12.storageBuffer8BitAccess;
  f12.shaderBufferInt64Atomics = has12.shaderBufferInt64Atomics;  // noodles' visibility buffer
  VkPhysicalDeviceVulkan11Features f11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES, &f12};
  f11.storageBuffer16BitAccess = has11.storageBuffer16BitAccess;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f11};
  features.features.samplerAnisotropy = has.features.samplerAnisotropy;
  features.features.shaderInt16 = has.features.shaderInt16;
  features.features.shaderInt64 = has.features.shaderInt64;
  features.features.fillModeNonSolid = has.features.fillModeNonSolid;
  features.features.shaderStorageImageWriteWithoutFormat = has.features.shaderStorageImageWriteWithoutFormat;
  // Storage images in the extended formats: glass's motion vectors (rg16f), noodles' baked flow (rgb10_a2).
  features.features.shaderStorageImageExtendedFormats = has.features.shaderStorageImageExtendedFormats;
  storageWriteWithoutFormat_ = has.features.shaderStorageImageWriteWithoutFormat;
  bufferInt64Atomics_ = has.features.shaderInt64 && has12.shaderBufferInt64Atomics;
  // Invocation counts only when asked (bench --pipeline-stats), like the compiler statistics below.
  countsInvocations_ = options.pipelineStatistics && has.features.pipelineStatisticsQuery;
  features.features.pipelineStatisticsQuery = countsInvocations_;

  std::vector<const char*> extensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
  if (options.surface) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  // DMA-BUF export (a published output's frames handed over without a copy through the CPU), only where
  // the driver offers all three; their other dependencies (image format lists, bind memory 2, sampler
  // Y'CbCr conversion) are core in Vulkan 1.3.
  {
    const auto offered = deviceExtensions(physical_);
    const std::array<const char*, 3> dmaBuf{VK_KHR_EXTERNAL_MEMORY_FD_EXTENSION_NAME,
                                            VK_EXT_EXTERNAL_MEMORY_DMA_BUF_EXTENSION_NAME,
                                            VK_EXT_IMAGE_DRM_FORMAT_MODIFIER_EXTENSION_NAME};
    exportsDmaBuf_ = std::all_of(dmaBuf.begin(), dmaBuf.end(), [&](const char* name) { return hasExtension(offered, name); });
    if (exportsDmaBuf_) extensions.insert(extensions.end(), dmaBuf.begin(), dmaBuf.end());
  }
  // Compiler statistics only when asked (bench --pipeline-stats): capturing them may change how a
  // driver caches its pipelines, and no other run reads them.
  VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR executableInfo{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
  if (options.pipelineStatistics && hasExtension(deviceExtensions(physical_), VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME)) {
    VkPhysicalDevicePipelineExecutablePropertiesFeaturesKHR supported{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PIPELINE_EXECUTABLE_PROPERTIES_FEATURES_KHR};
    VkPhysicalDeviceFeatures2 query{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported};
    vkGetPhysicalDeviceFeatures2(physical_, &query);
    if (supported.pipelineExecutableInfo) {
      executableInfo.pipelineExecutableInfo = VK_TRUE;
      f13.pNext = &executableInfo;
      extensions.push_back(VK_KHR_PIPELINE_EXECUTABLE_PROPERTIES_EXTENSION_NAME);
    }
  }

  const float priority = 1.0f;
  const VkDeviceQueueCreateInfo queueInfo{
      VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, nullptr, 0, queueFamily_, 1, &priority};
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(physical_, &info, nullptr, &device_));
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

  cmdPushDescriptorSet =
      reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
  if (exportsDmaBuf_) {
    getMemoryFd = reinterpret_cast<PFN_vkGetMemoryFdKHR>(vkGetDeviceProcAddr(device_, "vkGetMemoryFdKHR"));
    getMemoryFdProperties =
        reinterpret_cast<PFN_vkGetMemoryFdPropertiesKHR>(vkGetDeviceProcAddr(device_, "vkGetMemoryFdPropertiesKHR"));
    getImageDrmFormatModifierProperties = reinterpret_cast<PFN_vkGetImageDrmFormatModifierPropertiesEXT>(
        vkGetDeviceProcAddr(device_, "vkGetImageDrmFormatModifierPropertiesEXT"));
    exportsDmaBuf_ = getMemoryFd && getMemoryFdProperties && getImageDrmFormatModifierProperties;
  }
  if (executableInfo.pipelineExecutableInfo) {
    getExecutableProperties_ = reinterpret_cast<PFN_vkGetPipelineExecutablePropertiesKHR>(
        vkGetDeviceProcAddr(device_, "vkGetPipelineExecutablePropertiesKHR"));
    getExecutableStatistics_ = reinterpret_cast<PFN_vkGetPipelineExecutableStatisticsKHR>(
        vkGetDeviceProcAddr(device_, "vkGetPipelineExecutableStatisticsKHR"));
    if (!getExecutableProperties_) getExecutableStatistics_ = nullptr;
  }
  if (instance.debugUtils()) {
    setName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(instance.handle(), "vkSetDebugUtilsObjectNameEXT"));
    beginLabel_ = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance.handle(), "vkCmdBeginDebugUtilsLabelEXT"));
    endLabel_ = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
        vkGetInstanceProcAddr(instance.handle(), "vkCmdEndDebugUtilsLabelEXT"));
  }

  oneShotPool_ = createCommandPool(*this, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT, "one-shot pool");
  timeline_ = createTimelineSemaphore(*this, "queue timeline");
  for (const Filter filter : {Filter::Nearest, Filter::Linear})
    for (const Address address : {Address::Clamp, Address::Repeat})
      for (const bool mipmaps : {false, true}) {
        VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
        samplerInfo.magFilter = samplerInfo.minFilter = filter == Filter::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
        samplerInfo.mipmapMode = filter == Filter::Linear ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
        samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW =
            address == Address::Clamp ? VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE : VK_SAMPLER_ADDRESS_MODE_REPEAT;
        samplerInfo.maxLod = mipmaps ? VK_LOD_CLAMP_NONE : 0.0f;
        VkSampler sampler;
        VK_CHECK(vkCreateSampler(device_, &samplerInfo, nullptr, &sampler));
        name(sampler, VK_OBJECT_TYPE_SAMPLER,
             fmt::format("{} {}{}", filter == Filter::Linear ? "linear" : "nearest",
                         address == Address::Clamp ? "clamp" : "repeat", mipmaps ? " mipmapped" : ""));
        samplers_[samplerIndex(filter, address, mipmaps)] = Unique<VkSampler>(device_, sampler);
      }
}

Device::~Device() {
  if (!device_) return;
  vkDeviceWaitIdle(device_);
  graveyard_.clear();
  for (auto& sampler : samplers_) sampler.reset();
  timeline_.reset();
  oneShotPool_.reset();
  vkDestroyDevice(device_, nullptr);
}

VkSampler Device::sampler(Filter filter, Address address, bool mipmaps) const {
  return samplers_[samplerIndex(filter, address, mipmaps)];
}

uint64_t Device::submit(const Submit& work) const {
  if (work.signal.size() > kMaxSignals) throw Error("too many semaphores signalled by one submission");
  std::array<VkSemaphoreSubmitInfo, kMaxSignals + 1> signal;  // no allocation per frame
  std::copy(work.signal.begin(), work.signal.end(), signal.begin());
  signal[work.signal.size()] = {VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO, nullptr, timeline_, submitted_ + 1,
                                VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0};
  const VkCommandBufferSubmitInfo commands{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO, nullptr, work.cmd, 0};
  VkSubmitInfo2 info{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  info.waitSemaphoreInfoCount = static_cast<uint32_t>(work.wait.size());
  info.pWaitSemaphoreInfos = work.wait.data();
  info.commandBufferInfoCount = work.cmd ? 1 : 0;
  info.pCommandBufferInfos = &commands;
  info.signalSemaphoreInfoCount = static_cast<uint32_t>(work.signal.size() + 1);
  info.pSignalSemaphoreInfos = signal.data();
  VK_CHECK(injectedFault(Fault::DeviceLost) != VK_SUCCESS ? VK_ERROR_DEVICE_LOST
                                                         : vkQueueSubmit2(queue_, 1, &info, VK_NULL_HANDLE));
  return ++submitted_;
}

uint64_t Device::completed() const {
  uint64_t value = 0;
  VK_CHECK(vkGetSemaphoreCounterValue(device_, timeline_, &value));
  return value;
}

void Device::wait(uint64_t serial) const {
  const VkSemaphore semaphore = timeline_;
  const VkSemaphoreWaitInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_WAIT_INFO, nullptr, 0, 1, &semaphore, &serial};
  VK_CHECK(vkWaitSemaphores(device_, &info, UINT64_MAX));
}

// Called by destructors, so it never throws: a lost device has nothing left running, and its
// objects may still be destroyed.
void Device::drainRetired() const {
  vkDeviceWaitIdle(device_);
  graveyard_.clear();
}

std::vector<std::string> Device::pipelineStatistics(VkPipeline pipeline) const {
  std::vector<std::string> lines;
  if (!capturesPipelineStatistics()) return lines;
  const VkPipelineInfoKHR info{VK_STRUCTURE_TYPE_PIPELINE_INFO_KHR, nullptr, pipeline};
  uint32_t count = 0;
  VK_CHECK(getExecutableProperties_(device_, &info, &count, nullptr));
  std::vector<VkPipelineExecutablePropertiesKHR> executables(count, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_PROPERTIES_KHR});
  VK_CHECK(getExecutableProperties_(device_, &info, &count, executables.data()));
  for (uint32_t i = 0; i < count; ++i) {
    const VkPipelineExecutableInfoKHR which{VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_INFO_KHR, nullptr, pipeline, i};
    uint32_t statistics = 0;
    VK_CHECK(getExecutableStatistics_(device_, &which, &statistics, nullptr));
    std::vector<VkPipelineExecutableStatisticKHR> values(statistics, {VK_STRUCTURE_TYPE_PIPELINE_EXECUTABLE_STATISTIC_KHR});
    VK_CHECK(getExecutableStatistics_(device_, &which, &statistics, values.data()));
    std::string line = executables[i].name;
    for (uint32_t k = 0; k < statistics; ++k) {
      const VkPipelineExecutableStatisticKHR& v = values[k];
      line += k == 0 ? ": " : ", ";
      line += v.name;
      line += ' ';
      switch (v.format) {
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_BOOL32_KHR: line += v.value.b32 ? "true" : "false"; break;
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_INT64_KHR: line += std::to_string(v.value.i64); break;
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_UINT64_KHR: line += std::to_string(v.value.u64); break;
        case VK_PIPELINE_EXECUTABLE_STATISTIC_FORMAT_FLOAT64_KHR: line += std::to_string(v.value.f64); break;
        default: line += '?';
      }
    }
    lines.push_back(std::move(line));
  }
  return lines;
}

VkFormatFeatureFlags Device::optimalTilingFeatures(VkFormat format) const {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(physical_, format, &properties);
  return properties.optimalTilingFeatures;
}

std::string Device::describe() const {
  const auto& p = properties_;
  return fmt::format("{} (driver {:#x}, Vulkan {}.{}.{})", p.deviceName, p.driverVersion,
                     VK_API_VERSION_MAJOR(p.apiVersion), VK_API_VERSION_MINOR(p.apiVersion),
                     VK_API_VERSION_PATCH(p.apiVersion));
}

Unique<VkDeviceMemory> Device::allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags wanted,
                                        VkMemoryPropertyFlags fallback, const void* next) const {
  for (VkMemoryPropertyFlags flags : {wanted, fallback}) {
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
      if (!(requirements.memoryTypeBits & (1u << i))) continue;
      if ((memory_.memoryTypes[i].propertyFlags & flags) != flags) continue;
      VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, next, requirements.size, i};
      VkDeviceMemory memory;
      VK_CHECK(injectedFault(Fault::OutOfMemory) != VK_SUCCESS ? VK_ERROR_OUT_OF_DEVICE_MEMORY
                                                               : vkAllocateMemory(device_, &info, nullptr, &memory));
      noteAllocated(memory, requirements.size);
      if (injectedDirtyMemory()) dirty(memory, i, requirements.size);
      return Unique<VkDeviceMemory>(device_, memory);
    }
  }
  throw Error(
      fmt::format("No Vulkan memory type fits a {} byte allocation with flags {:#x}", requirements.size, wanted));
}

// VITRINE_INJECT=dirty-memory (fault_injection.h): fresh memory the host can reach filled with garbage.
void Device::dirty(VkDeviceMemory memory, uint32_t type, VkDeviceSize size) const {
  const VkMemoryPropertyFlags flags = memory_.memoryTypes[type].propertyFlags;
  if (!(flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)) return;
  void* bytes = nullptr;
  VK_CHECK(vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &bytes));
  std::memset(bytes, 0x3f, size_t(size));
  if (!(flags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)) {
    const VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE, nullptr, memory, 0, VK_WHOLE_SIZE};
    VK_CHECK(vkFlushMappedMemoryRanges(device_, 1, &range));
  }
  vkUnmapMemory(device_, memory);
}

void Device::submitNow(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, oneShotPool_,
                                    VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
  VkCommandBuffer cmd;
  VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &cmd));
  // Freed on every way out: a recording callback that throws must not leak its command buffer.
  struct Free {
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    ~Free() { vkFreeCommandBuffers(device, pool, 1, &cmd); }
  } freeOnExit{device_, oneShotPool_, cmd};
  const VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                       VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  VK_CHECK(vkEndCommandBuffer(cmd));
  wait(submit({cmd, {}, {}}));
}

void Device::waitIdle() const { VK_CHECK(vkDeviceWaitIdle(device_)); }

void Device::name(VkObjectType type, uint64_t handle, const std::string& label) const {
  if (!setName_ || !handle) return;
  const VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT, nullptr, type, handle,
                                           label.c_str()};
  setName_(device_, &info);
}

void Device::beginLabel(VkCommandBuffer cmd, const char* label) const {
  if (!beginLabel_) return;
  const VkDebugUtilsLabelEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_LABEL_EXT, nullptr, label, {0.9f, 0.6f, 0.1f, 1.0f}};
  beginLabel_(cmd, &info);
}

void Device::endLabel(VkCommandBuffer cmd) const {
  if (endLabel_) endLabel_(cmd);
}

}  // namespace vitrine::gpu
