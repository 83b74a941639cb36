#include "host/present/swapchain.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <span>
#include <string>
#include <utility>

#include "gpu/check.h"
#include "gpu/sync_objects.h"
#include "host/present/window.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace vitrine::host {
namespace {

// Every swapchain image ends in the overlay's render pass.
constexpr VkImageUsageFlags kBlitUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
constexpr VkImageUsageFlags kComputeUsage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
constexpr VkFormatFeatureFlags kBlitFeatures = VK_FORMAT_FEATURE_BLIT_DST_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
constexpr VkFormatFeatureFlags kComputeFeatures =
    VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT;
constexpr VkFormat kUnormFormats[] = {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM};
constexpr VkFormat kSrgbFormats[] = {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_A8B8G8R8_SRGB_PACK32};

// The first of `wanted` the surface offers, in the sRGB colour space, with `features` on this device.
std::optional<VkSurfaceFormatKHR> findFormat(const gpu::Device& device, const std::vector<VkSurfaceFormatKHR>& offered,
                                             std::span<const VkFormat> wanted, VkFormatFeatureFlags features) {
  for (VkFormat format : wanted) {
    VkFormatProperties properties;
    vkGetPhysicalDeviceFormatProperties(device.physical(), format, &properties);
    if ((properties.optimalTilingFeatures & features) != features) continue;
    for (const auto& candidate : offered)
      if (candidate.format == format && candidate.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return candidate;
  }
  return std::nullopt;
}

// How often the monitor showing the window refreshes (monitorShowing); 60 Hz where the display does
// not say (Xvfb reports 0).
std::chrono::nanoseconds refreshInterval(GLFWwindow* window) {
  GLFWmonitor* monitor = window ? monitorShowing(window) : glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
  const int hertz = mode && mode->refreshRate > 0 ? mode->refreshRate : 60;
  return std::chrono::nanoseconds(1'000'000'000 / hertz);
}

VkCompositeAlphaFlagBitsKHR compositeAlpha(VkCompositeAlphaFlagsKHR supported) {
  for (auto mode : {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
                    VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR})
    if (supported & mode) return mode;
  return VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
}

}  // namespace

Swapchain::Swapchain(const gpu::Device& device, VkSurfaceKHR surface, GLFWwindow* window, VkExtent2D framebuffer,
                     bool vsync)
    : device_(device), surface_(surface), window_(window), presentation_(choosePresentation(device, surface)) {
  std::string why = "the surface's format is not the presenter's";
  // Only where the swapchain would draw in the same format, so that falling back to it (build) leaves
  // the overlay's render pass, made for format(), valid.
  if (presentation_.computeWrites && presentation_.format.format == ShmPresenter::kFormat)
    shm_ = ShmPresenter::create(device, window, &why);
  static bool said = false;  // once a run: every output window decides alike
  if (!std::exchange(said, true) && device.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
    const std::string path =
        shm_ ? "through X shared memory (a software device)" : fmt::format("through Vulkan's swapchain ({})", why);
    std::fprintf(stderr, "vitrine: frames reach the window %s\n", path.c_str());
  }
  build(framebuffer, vsync);
}

// Compute first: on compute-first GPUs a 4K blit costs as much as a whole scene.
Swapchain::Presentation Swapchain::choosePresentation(const gpu::Device& device, VkSurfaceKHR surface) {
  VkSurfaceCapabilitiesKHR caps;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device.physical(), surface, &caps));
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical(), surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> offered(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device.physical(), surface, &count, offered.data()));
  const auto supports = [&](VkImageUsageFlags usage) { return (caps.supportedUsageFlags & usage) == usage; };
  if (device.storageWriteWithoutFormat() && supports(kComputeUsage))
    if (auto format = findFormat(device, offered, kUnormFormats, kComputeFeatures))
      return {*format, kComputeUsage, true};
  if (supports(kBlitUsage))
    if (auto format = findFormat(device, offered, kSrgbFormats, kBlitFeatures)) return {*format, kBlitUsage, false};
  throw Error(
      "The window surface offers neither a storage-capable UNORM format nor an 8-bit sRGB format that can "
      "be blitted to; Vitrine cannot present to it.");
}

bool Swapchain::fits(VkExtent2D framebuffer, bool vsync) const {
  return !stale_ && vsync == vsync_ && framebuffer.width == builtFor_.width && framebuffer.height == builtFor_.height;
}

void Swapchain::recreate(VkExtent2D framebuffer, bool vsync) { build(framebuffer, vsync); }

VkPresentModeKHR Swapchain::presentMode(bool vsync) const {
  if (vsync) return VK_PRESENT_MODE_FIFO_KHR;  // the one mode every driver has
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(device_.physical(), surface_, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(device_.physical(), surface_, &count, modes.data()));
  // Mailbox shows the newest frame without tearing; immediate is the fallback that may tear.
  for (auto wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), wanted) != modes.end()) return wanted;
  return VK_PRESENT_MODE_FIFO_KHR;
}

void Swapchain::build(VkExtent2D framebuffer, bool vsync) {
  if (ShmPresenter* presenter = shm_ ? shm_.get() : parkedShm_.get()) {
    const std::string refused = presenter->build(framebuffer);
    device_.retire(std::move(renderFinished_));  // frames in flight may still signal them
    renderFinished_.clear();
    if (refused.empty()) {
      if (parkedShm_) {  // the window fits again: its frames leave Vulkan's swapchain
        shm_ = std::move(parkedShm_);
        device_.retire(std::move(views_));
        device_.retire(std::move(swapchain_));
        views_.clear();
        images_.clear();
        std::fprintf(stderr, "vitrine: frames reach a %ux%u window through X shared memory again\n",
                     framebuffer.width, framebuffer.height);
      }
      shm_->pace(vsync ? refreshInterval(window_) : std::chrono::nanoseconds(0));
      for (uint32_t i = 0; i < shm_->imageCount(); ++i)
        renderFinished_.push_back(gpu::createSemaphore(device_, fmt::format("render finished {}", i)));
      extent_ = framebuffer;
    } else if (shm_) {
      // Vulkan's swapchain draws the same pixels, only slower on a software device: the window goes on.
      std::fprintf(stderr, "vitrine: frames reach a %ux%u window through Vulkan's swapchain until it fits (%s)\n",
                   framebuffer.width, framebuffer.height, refused.c_str());
      parkedShm_ = std::move(shm_);
    }
  }
  if (!shm_) buildSwapchain(framebuffer, vsync);
  builtFor_ = framebuffer;
  vsync_ = vsync;
  stale_ = false;
}

void Swapchain::buildSwapchain(VkExtent2D framebuffer, bool vsync) {
  VkSurfaceCapabilitiesKHR caps;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(device_.physical(), surface_, &caps));
  // 0xFFFFFFFF means the surface takes its size from the swapchain, i.e. from the framebuffer.
  extent_ = caps.currentExtent.width != UINT32_MAX
                ? caps.currentExtent
                : VkExtent2D{std::clamp(framebuffer.width, caps.minImageExtent.width, caps.maxImageExtent.width),
                             std::clamp(framebuffer.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
  // One image more than the minimum, so acquiring rarely waits on the presentation engine.
  uint32_t imageCount = caps.minImageCount + 1;
  if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface_;
  info.minImageCount = imageCount;
  info.imageFormat = presentation_.format.format;
  info.imageColorSpace = presentation_.format.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = presentation_.usage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = compositeAlpha(caps.supportedCompositeAlpha);
  info.presentMode = presentMode(vsync);
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR swapchain;
  VK_CHECK(vkCreateSwapchainKHR(device_, &info, nullptr, &swapchain));
  // Frames in flight still use the old swapchain's images, views and semaphores: retire them
  // behind those frames instead of waiting for the device.
  if (swapchain_) {
    device_.retire(std::move(renderFinished_));
    device_.retire(std::move(views_));
    device_.retire(std::move(swapchain_));
  }
  swapchain_ = gpu::Unique<VkSwapchainKHR>(device_, swapchain);
  device_.name(swapchain, VK_OBJECT_TYPE_SWAPCHAIN_KHR, "swapchain");

  uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(device_, swapchain, &count, nullptr));
  images_.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(device_, swapchain, &count, images_.data()));
  views_.clear();
  renderFinished_.clear();
  for (uint32_t i = 0; i < count; ++i) {
    device_.name(images_[i], VK_OBJECT_TYPE_IMAGE, fmt::format("swapchain image {}", i));
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = images_[i];
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = presentation_.format.format;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view;
    VK_CHECK(vkCreateImageView(device_, &viewInfo, nullptr, &view));
    device_.name(view, VK_OBJECT_TYPE_IMAGE_VIEW, fmt::format("swapchain view {}", i));
    views_.emplace_back(device_, view);
    renderFinished_.push_back(gpu::createSemaphore(device_, fmt::format("render finished {}", i)));
  }
}

std::optional<uint32_t> Swapchain::acquire(VkSemaphore acquired) {
  if (shm_) return shm_->acquire(acquired);
  uint32_t index = 0;
  const VkResult result = vkAcquireNextImageKHR(device_, swapchain_, UINT64_MAX, acquired, VK_NULL_HANDLE, &index);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) {
    stale_ = true;
    return std::nullopt;
  }
  VK_CHECK(result);
  // Suboptimal still signals the semaphore, so this frame is drawn and the swapchain rebuilt after it.
  if (result == VK_SUBOPTIMAL_KHR) stale_ = true;
  return index;
}

void Swapchain::present(uint32_t image) {
  if (shm_) {
    // A window moved onto a monitor of another rate keeps its size (no build): looked at every
    // kPacedPresents presents, about a second at 60 Hz, for a few X round trips.
    if (vsync_ && ++presentsPaced_ == kPacedPresents) {
      presentsPaced_ = 0;
      shm_->pace(refreshInterval(window_));
    }
    return shm_->present(image, renderFinished_[image]);
  }
  VkSwapchainKHR swapchain = swapchain_;
  VkSemaphore wait = renderFinished_[image];
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &wait;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain;
  info.pImageIndices = &image;
  const VkResult result = vkQueuePresentKHR(device_.queue(), &info);
  if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) {
    stale_ = true;
    return;
  }
  VK_CHECK(result);
}

}  // namespace vitrine::host
