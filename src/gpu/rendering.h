#pragma once
// A dynamic-rendering scope: transitions its attachments, begins rendering with their load/clear and
// store operations and an optional MSAA resolve, sets a full viewport and scissor, and ends rendering
// when it goes out of scope. The one place vkCmdBeginRendering is called.
#include "gpu/resources.h"

#include <optional>
#include <vector>

namespace vitrine::gpu {

struct ColorAttachment {
  Image* image = nullptr;
  std::optional<VkClearColorValue> clear;  // none: keep (load) the contents
  Image* resolve = nullptr;                // multisampled image averaged into this one
  bool store = true;                       // false: the contents are not needed after the pass
};

struct DepthAttachment {
  Image* image = nullptr;
  std::optional<float> clear = 0.0f;  // reverse-Z: 0 is infinitely far
  bool store = false;                 // true when a later pass reads it (use::DepthRead)
};

struct RenderingDesc {
  std::vector<ColorAttachment> colors;
  std::optional<DepthAttachment> depth;
};

class Rendering {
 public:
  Rendering(VkCommandBuffer cmd, const RenderingDesc& desc);
  ~Rendering();
  Rendering(const Rendering&) = delete;
  Rendering& operator=(const Rendering&) = delete;
  VkExtent2D extent() const { return extent_; }

 private:
  VkCommandBuffer cmd_;
  VkExtent2D extent_{};
};

}  // namespace vitrine::gpu
