#pragma once
// F12: the scene's HDR target as EXR (linear) and PNG. The copy is recorded in the frame's own
// command buffer and the files are written once that frame's fence has signalled, so a screenshot
// never stalls the GPU.
#include "gpu/pass_timer.h"
#include "gpu/resources.h"

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
  // After the scene renderer, which leaves `target` a transfer source: copies it if one was requested.
  void record(VkCommandBuffer cmd, uint32_t slot, gpu::Image& target, std::string_view scene,
              gpu::PassTimer* timer);
  // Once `slot`'s fence has signalled: writes the screenshot taken in it, if any, and says how that went.
  std::optional<std::string> collect(uint32_t slot);

 private:
  struct Pending {
    gpu::Buffer pixels;
    VkExtent2D extent;
    std::string stem;  // vitrine-<scene>-<YYYYmmdd-HHMMSS>
  };
  std::string write(const Pending& shot) const;

  const gpu::Device& device_;
  std::filesystem::path folder_;
  std::vector<std::optional<Pending>> pending_;  // per frame in flight
  bool requested_ = false;
};

}  // namespace vitrine::host
