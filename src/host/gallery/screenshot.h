#pragma once
// F12: the scene's picture at the window's size (its HDR target scaled as the present pass scales it;
// an output's warp, the flash guard and a cross-fade are the window's, not the picture's), as EXR (linear) and PNG; the size the scene rendered at (its quality tier's
// render scale) is written into the files' metadata. The copy is recorded in the frame's own command
// buffer and the files are written once that frame's fence has signalled, so a screenshot never
// stalls the GPU.
#include "gpu/pass_timer.h"
#include "gpu/resources.h"
#include "image/image_io.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::host {

class Screenshots {
 public:
  Screenshots(const gpu::Device& device, uint32_t framesInFlight, std::filesystem::path folder);

  void request() { requested_ = true; }
  bool requested() const { return requested_; }
  // `shown` (a transfer source) is the window's picture; `rendered` the size the scene drew it at.
  // Copies it if a screenshot was requested.
  void record(VkCommandBuffer cmd, uint32_t slot, gpu::Image& shown, VkExtent2D rendered, std::string_view scene,
              gpu::PassTimer* timer);
  // Once `slot`'s fence has signalled: writes the screenshot taken in it, if any, and says how that went.
  std::optional<std::string> collect(uint32_t slot);
  // What the files say about themselves: the scene, the window's size and the size it rendered at.
  static ImageNotes notes(std::string_view scene, VkExtent2D shown, VkExtent2D rendered);

 private:
  struct Pending {
    gpu::Buffer pixels;
    VkExtent2D extent;
    VkExtent2D rendered;
    std::string scene;
    std::string stem;  // vitrine-<scene>-<YYYYmmdd-HHMMSS>
  };
  std::string write(const Pending& shot) const;

  const gpu::Device& device_;
  std::filesystem::path folder_;
  std::vector<std::optional<Pending>> pending_;  // per frame in flight
  bool requested_ = false;
};

}  // namespace vitrine::host
