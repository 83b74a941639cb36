#pragma once
// Another output of the gallery (a second projector, a monitor beside the one with the menu): a window
// with no frame, fullscreen on its monitor or at a place given in pixels, showing the frame the scene
// rendered once for the main window through this output's own warp (its region, turn, pin and soft
// edges). The main window has the menu and the cursor; keys pressed while an output has the focus
// go to the main window (Window::takeKeysOf).
#include "gpu/device.h"
#include "host/present/output.h"
#include "host/present/swapchain.h"
#include "host/present/window.h"
#include "maths/output_warp.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

struct GLFWwindow;

namespace vitrine::host {

// Where an output goes and how it shows the frame: one entry of --outputs FILE.json,
//   [{"monitor": "1", "warp": {"region": [0.5, 0, 1, 1]}}, {"window": [1280, 0, 640, 360], "name": "left"}]
// "monitor" (an index or part of a name): fullscreen there; "window": [x, y, width, height] on the
// desktop, without a frame; "pipewire": "NODE", a PipeWire video source of that name (rig/pipewire_source.h),
// offered at "size": [width, height] (else the main window's). One of the three; "warp" as in
// --output-warp. "name": what the settings file keeps this output's warp under (projector setup's pin):
// by default its monitor or node, else "output N".
struct OutputPlacement {
  std::string monitor;
  std::optional<std::array<int, 4>> window;
  std::string pipewire;
  std::optional<std::array<int, 2>> size;  // a published output's
  std::optional<maths::OutputWarp> warp;  // none given: the settings file's, else the identity
  std::string name;
};
// Throws vitrine::Error naming the file and the entry.
std::vector<OutputPlacement> readOutputs(const std::filesystem::path& file);

class OutputWindow final : public Output {
 public:
  // GLFW is up (the main window's); the device presents from its queue to this window's surface, or
  // this throws vitrine::Error saying so.
  OutputWindow(const gpu::Instance& instance, const gpu::Device& device, const OutputPlacement& placement, bool vsync,
               uint32_t framesInFlight, int index);
  ~OutputWindow() override;

  // False when the window is hidden or its swapchain out of date (rebuilt for the next frame).
  bool acquire(uint32_t slot, bool vsync) override;
  BlitDestination destination(VkPipelineStageFlags2 acquireStage) const override;
  std::pair<VkSemaphore, VkSemaphore> semaphores(uint32_t slot) const override {
    return {acquired_[slot], swapchain_->renderFinished(*image_)};
  }
  void present() override;
  VkExtent2D extent() const override { return swapchain_->extent(); }
  GLFWwindow* handle() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
  std::optional<Surface> surface_;
  std::optional<Swapchain> swapchain_;
  std::vector<gpu::Unique<VkSemaphore>> acquired_;  // one a frame slot
  std::optional<uint32_t> image_;
};

}  // namespace vitrine::host
