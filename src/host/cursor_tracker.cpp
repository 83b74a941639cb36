#include "host/cursor_tracker.h"

#include <algorithm>

namespace vitrine::host {

void CursorTracker::observe(const Pointer& pointer, bool menuWantsMouse) {
  const glm::vec2 size(std::max(1u, pointer.framebuffer.width), std::max(1u, pointer.framebuffer.height));
  const glm::vec2 normalized = pointer.pixels / size;
  const bool wasDragging = state_.dragging;
  if (pointer.leftPressed && !menuWantsMouse) state_.dragging = true;
  if (!pointer.leftHeld) state_.dragging = false;
  if (state_.dragging && wasDragging) state_.dragDelta += normalized - state_.normalized;
  if (!menuWantsMouse) state_.wheel += pointer.wheel;
  state_.present = pointer.inside && !menuWantsMouse;
  state_.pixels = pointer.pixels;
  state_.normalized = normalized;
}

CursorInput CursorTracker::take() {
  const CursorInput taken = state_;
  state_.dragDelta = glm::vec2(0.0f);
  state_.wheel = 0.0f;
  return taken;
}

}  // namespace vitrine::host
