#pragma once
// The view in world units. It is always the original's canvas height down and as wide as the window's
// aspect makes it, so the shapes keep their size against the view's height at any window size; the
// scene's positions (instances, drags, shuffles) and the camera are all in these units.
#include <glm/vec2.hpp>
#include <vulkan/vulkan.h>

namespace vitrine::glass {

inline constexpr float kViewHeight = 1073.0f;  // world units down the view: the original's canvas height

// World units across and down a view of `extent` pixels.
inline glm::vec2 viewSize(VkExtent2D extent) {
  const float aspect = extent.height ? float(extent.width) / float(extent.height) : 1.0f;
  return {kViewHeight * aspect, kViewHeight};
}

}  // namespace vitrine::glass
