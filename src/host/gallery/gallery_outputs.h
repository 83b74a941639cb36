#pragma once
// The gallery's outputs: the main window (output 0) and the others (--outputs, numbered from 1), each
// showing the one frame through its own warp, and projector setup (F7) moving one output's corner pin at
// a time, kept in the settings file under the output's name (the main window's also in --output-warp's
// file). The frame loop asks it how the main window shows the frame, has it draw every other output
// after the main window, and gives it setup's keys and mouse. A new kind of output (host/present/output.h) is
// added here beside the windows and is drawn and pinned like them.
#include "host/gallery/gallery_settings.h"
#include "host/present/output.h"
#include "host/pointer.h"
#include "host/present/projector_setup.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vitrine::gpu {
class Device;
class Instance;
}  // namespace vitrine::gpu

namespace vitrine::host {

class Window;

class GalleryOutputs {
 public:
  static constexpr std::string_view kMain = "main";  // the main window's name in the settings file
  // Throws vitrine::Error, starting with `where`, when the frame `warp` asks of an output of `extent`
  // pixels is more than the device draws (checkWarpedFrame).
  using FrameCheck = std::function<void(VkExtent2D extent, const maths::OutputWarp& warp, std::string_view where)>;

  // `mainWarp`: --output-warp's, read from `warpFile`, which wins over the settings file; without one
  // the main window of `mainExtent` pixels shows the settings file's pin.
  GalleryOutputs(GallerySettings& settings, FrameCheck check, std::string warpFile,
                 std::optional<maths::OutputWarp> mainWarp, VkExtent2D mainExtent);
  // --outputs FILE's windows, each checked against the device; keys pressed in them go to `main`.
  void openWindows(const gpu::Instance& instance, const gpu::Device& device, Window& main, const std::string& file,
                   bool vsync, uint32_t framesInFlight);
  // The next output. `warpGiven`: it brought its own warp (checked here, naming `where`); else it shows
  // the pin the settings file keeps under its name.
  void add(std::unique_ptr<Output> output, bool warpGiven, std::string_view where);

  size_t count() const { return others_.size() + 1; }
  std::string_view name(size_t output) const { return output == 0 ? kMain : others_[output - 1]->name(); }
  VkExtent2D extent(size_t output, VkExtent2D mainExtent) const {
    return output == 0 ? mainExtent : others_[output - 1]->extent();
  }
  maths::OutputWarp& warpOf(size_t output);
  // How the main window shows the frame: its own warp (null: the whole frame, square-on), or during
  // setup of another output, that output's, to drag its corners on.
  const maths::OutputWarp* shownWarp();

  // Projector setup, from the main window's pin.
  void startSetup();
  bool setupActive() const { return setup_.active(); }
  struct SetupKey {
    bool used = false;   // the key was setup's
    bool ended = false;  // setup is over
    std::string note;    // what became of the pin, for the note on the screen
  };
  // A key (GLFW code) during setup, `shift` held, the main window `mainExtent` pixels. Enter keeps the
  // pin, Esc puts it back, F7 keeps it and goes on to the next output's (round to the main window).
  SetupKey setupKey(int key, bool shift, VkExtent2D mainExtent);
  void setupPointer(const Pointer& pointer);
  void drawSetup(VkExtent2D mainExtent);  // the handles, between the overlay's beginFrame and its record
  // The output whose setup the main window shows from now on, once each time it changes, when `ready`
  // (its card built); the caller says it on the console.
  std::optional<std::string_view> setupNewlyShown(bool ready);

  // Once a frame, after the main window's present pass: the frame `shown` onto every other output that
  // takes one now, mixed with `fade`, through its own warp. Returns the semaphores the submission waits
  // for and signals for them (an output drawn into an image of its own has none).
  std::vector<std::pair<VkSemaphore, VkSemaphore>> record(VkCommandBuffer cmd, uint32_t slot, SceneRenderer& renderer,
                                                          const Crossfade& fade, bool vsync,
                                                          VkPipelineStageFlags2 acquireStage, const FrameInput& shown);
  // How each output besides the main window fares (Output::health), in order.
  std::vector<Output::Health> health() const;
  void present();  // after the submission

 private:
  // The settings file's pin for `output` of `extent` pixels; one this build refuses, or whose frame is
  // past the device, is a warning and the output shows the whole frame.
  std::optional<maths::OutputWarp> savedWarp(std::string_view output, VkExtent2D extent);
  std::string keep(size_t output);  // the pin into the settings (and the warp file); returns the note
  GallerySettings& settings_;
  FrameCheck check_;
  std::string warpFile_;
  std::optional<maths::OutputWarp> mainWarp_;  // none: the whole frame
  std::vector<std::unique_ptr<Output>> others_;
  ProjectorSetup setup_;
  size_t setupOutput_ = 0;            // the output whose pin setup moves
  std::optional<size_t> setupShown_;  // the output whose setup the console last said is showing
};

}  // namespace vitrine::host
