#include "host/cursor_tracker.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace vitrine::host {

constexpr float kRestingSlackPixels = 2.0f;

void CursorTracker::observe(const Pointer& pointer, bool menuWantsMouse) {
  const glm::vec2 size(std::max(1u, pointer.framebuffer.width), std::max(1u, pointer.framebuffer.height));
  const glm::vec2 normalized = pointer.pixels / size;
  const bool wasDragging = state_.dragging;
  if (pointer.leftPressed && !menuWantsMouse) state_.dragging = true;
  if (!pointer.leftHeld) state_.dragging = false;
  if (state_.dragging && wasDragging) state_.dragDelta += normalized - state_.normalized;
  if (!menuWantsMouse) state_.wheel += pointer.wheel;
  if (!engaged_) {  // a resting pointer engages once it moves (more than a pixel: a window settling), presses or leaves
    if (!restingAt_ && pointer.inside) restingAt_ = pointer.pixels;
    engaged_ = !pointer.inside || pointer.leftPressed || pointer.leftHeld || pointer.wheel != 0.0f ||
               glm::length(pointer.pixels - *restingAt_) > kRestingSlackPixels;
  }
  state_.present = engaged_ && pointer.inside && !menuWantsMouse;
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
