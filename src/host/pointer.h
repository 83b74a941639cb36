#pragma once
// The mouse as the frame loop sees it. Its own header so that what consumes a pointer (the cursor
// tracker, the input-script player) needs nothing of the window or GLFW.
#include <vulkan/vulkan.h>

#include <glm/vec2.hpp>

#include <optional>

namespace vitrine::host {

// Positions in framebuffer pixels, events since the last take.
struct Pointer {
  glm::vec2 pixels{0.0f};
  VkExtent2D framebuffer{};
  bool leftHeld = false;
  bool leftPressed = false;  // a press happened since the last take, even if already released
  float wheel = 0.0f;        // scroll steps since the last take
  bool inside = false;       // the cursor is over the view (not elsewhere on the desktop)
  // Where the left button was let go, when it was since the last take: a slow frame can hold a drag's
  // last moves and its release, and `pixels` is where the cursor went after.
  std::optional<glm::vec2> releasedAt;
};

}  // namespace vitrine::host
