#pragma once
// Dear ImGui drawn over the presented image. Debian's ImGui 1.86 Vulkan backend predates dynamic
// rendering, so the overlay has a small render pass of its own: it loads what the scene renderer wrote
// into the swapchain image, draws the widgets and leaves the image ready to present.
#include "gpu/device.h"
#include "gpu/pass_timer.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;
struct ImFont;

namespace vitrine::host {

class Swapchain;

class Overlay {
 public:
  struct Fonts {  // woff2 files rendered through FreeType; Dear ImGui's built-in font where absent
    std::optional<std::filesystem::path> body, titles;
  };
  // `format` is the swapchain's; it must stay the same for the overlay's lifetime. `layoutFile`: where
  // Dear ImGui keeps the windows' places and folds (and what keepInIni adds); empty: nowhere.
  // `forgetLayout`: start from the default layout (the file is rewritten).
  Overlay(const gpu::Device& device, GLFWwindow* window, VkFormat format, uint32_t framesInFlight,
          const Fonts& fonts, std::filesystem::path layoutFile = {}, bool forgetLayout = false);

  void attach(const Swapchain& swapchain);  // framebuffers over its current images
  void beginFrame();                        // widgets may be drawn from here until record()
  // Draws the widgets into swapchain image `image`, which the scene renderer left as a colour attachment.
  void record(VkCommandBuffer cmd, uint32_t image, gpu::PassTimer* timer);

  bool wantsMouse() const;  // the pointer is over, or dragging, a widget
  bool wantsText() const;   // a text field has the keyboard
  bool wantsKeyboard() const;  // a widget has the keyboard, from this frame's widgets (menuHasKeyboard)
  ImFont* titleFont() const { return context_.titles; }  // null: use the current font
  // One line per font file that was given but FreeType could not use, naming it and the reason.
  const std::vector<std::string>& fontProblems() const { return context_.fontProblems; }

 private:
  struct Context {  // the ImGui context, its fonts and its GLFW backend
    Context(GLFWwindow* window, const Fonts& fonts, std::filesystem::path layoutFile, bool forgetLayout);
    ~Context();
    ImFont* titles = nullptr;
    std::string layoutFile;  // what io.IniFilename points to
    std::vector<std::string> fontProblems;
  };
  struct Renderer {  // the ImGui Vulkan backend, shut down before the render pass and pool it uses
    Renderer(const gpu::Device& device, VkDescriptorPool pool, VkRenderPass renderPass, uint32_t framesInFlight);
    ~Renderer();
  };

  const gpu::Device& device_;
  gpu::Unique<VkDescriptorPool> pool_;
  gpu::Unique<VkRenderPass> renderPass_;
  std::vector<gpu::Unique<VkFramebuffer>> framebuffers_;
  VkExtent2D extent_{};
  Context context_;
  Renderer renderer_;
};

}  // namespace vitrine::host
