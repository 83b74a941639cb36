#pragma once
// Turns the window's pointer into a scene's CursorInput. A drag belongs to the scene only when its
// press did not land on the menu. Movement and scrolling add up until a simulation step takes them,
// so a frame that runs no step loses nothing and a frame that runs several does not repeat it.
#include "host/pointer.h"
#include "scenes/scene.h"

namespace vitrine::host {

class CursorTracker {
 public:
  void observe(const Pointer& pointer, bool menuWantsMouse);  // once per rendered frame
  CursorInput take();                                         // once per simulation step

 private:
  CursorInput state_;
};

}  // namespace vitrine::host
