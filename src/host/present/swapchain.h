#pragma once
// The window's swapchain. The scene renderer writes the linear HDR target into its images either with
// its compute present (a UNORM storage image; the shader encodes sRGB) or, where storage images are
// not offered, with a blit into an sRGB image (the blit encodes). Each image has its own
// render-finished semaphore: the presentation engine may still wait on one after its frame's fence
// has signalled, and only acquiring that image again proves it is free. On a software device with an
// X11 window it hands the frames to an ShmPresenter instead of Vulkan's swapchain (shm_presenter.h
// says why), except while the window is bigger than the shared memory the system grants; everything
// else is the same.
#include "gpu/device.h"
#include "host/present/shm_presenter.h"

#include <memory>
#include <optional>
#include <vector>

struct GLFWwindow;

namespace vitrine::host {

class Swapchain {
 public:
  Swapchain(const gpu::Device& device, VkSurfaceKHR surface, GLFWwindow* window, VkExtent2D framebuffer, bool vsync);

  // False when the surface has moved on: resized, suboptimal, or a different vsync asked for.
  bool fits(VkExtent2D framebuffer, bool vsync) const;
  void recreate(VkExtent2D framebuffer, bool vsync);  // the old one is retired, not waited for

  // The next image to draw, signalling `acquired` when it may be written; empty when out of date.
  std::optional<uint32_t> acquire(VkSemaphore acquired);
  // Shows the image once its render-finished semaphore is signalled.
  void present(uint32_t image);

  VkFormat format() const { return shm_ ? ShmPresenter::kFormat : presentation_.format.format; }
  // True: images are written by compute through view(i), which must encode sRGB. False: blitted.
  bool computeWrites() const { return shm_ || presentation_.computeWrites; }
  VkExtent2D extent() const { return extent_; }
  uint32_t imageCount() const { return uint32_t(renderFinished_.size()); }
  VkImage image(uint32_t index) const { return shm_ ? shm_->image(index) : images_[index]; }
  VkImageView view(uint32_t index) const { return shm_ ? shm_->view(index) : VkImageView(views_[index]); }
  VkSemaphore renderFinished(uint32_t index) const { return renderFinished_[index]; }

 private:
  struct Presentation {
    VkSurfaceFormatKHR format;
    VkImageUsageFlags usage;
    bool computeWrites;
  };
  static Presentation choosePresentation(const gpu::Device& device, VkSurfaceKHR surface);
  void build(VkExtent2D framebuffer, bool vsync);
  void buildSwapchain(VkExtent2D framebuffer, bool vsync);
  VkPresentModeKHR presentMode(bool vsync) const;

  const gpu::Device& device_;
  VkSurfaceKHR surface_;
  GLFWwindow* window_;
  Presentation presentation_;  // chosen once: what a surface supports does not change with its size
  std::unique_ptr<ShmPresenter> shm_;  // set where it works: then there is no VkSwapchainKHR
  // The presenter while the window is bigger than the shared memory the system grants: tried again at
  // each new size, and back in shm_ once the window fits.
  std::unique_ptr<ShmPresenter> parkedShm_;
  gpu::Unique<VkSwapchainKHR> swapchain_;
  std::vector<VkImage> images_;  // owned by the swapchain
  std::vector<gpu::Unique<VkImageView>> views_;
  std::vector<gpu::Unique<VkSemaphore>> renderFinished_;
  VkExtent2D extent_{};
  VkExtent2D builtFor_{};
  bool vsync_ = true;
  bool stale_ = false;
  static constexpr uint32_t kPacedPresents = 60;  // presents between asking which monitor shows the window
  uint32_t presentsPaced_ = 0;
};

}  // namespace vitrine::host
