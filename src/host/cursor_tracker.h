#pragma once
// Turns the window's pointer into a scene's CursorInput. A drag belongs to the scene only when its
// press did not land on the menu. Movement and scrolling add up until a simulation step takes them,
// so a frame that runs no step loses nothing and a frame that runs several does not repeat it.
#include "host/pointer.h"
#include "frame/frame_input.h"

#include <optional>

namespace vitrine::host {

class CursorTracker {
 public:
  // `waitForMovement`: a pointer already resting over the view when the tracker first sees it (a window
  // opened under it) is not the scene's until it moves, presses or leaves and comes back: a gallery that
  // starts under a resting pointer shows its first look, not whatever the pointer would start there.
  explicit CursorTracker(bool waitForMovement = false) : engaged_(!waitForMovement) {}
  void observe(const Pointer& pointer, bool menuWantsMouse);  // once per rendered frame
  CursorInput take();                                         // once per simulation step

 private:
  CursorInput state_;
  bool engaged_;
  std::optional<glm::vec2> restingAt_;  // where a resting pointer was first seen, until it moves
};

}  // namespace vitrine::host
