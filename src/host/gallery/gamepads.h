#pragma once
// Gamepads as live sources, through GLFW's gamepad API (standard layout, hot-plugged): joystick N's
// axes as pad.N.axis.K (0..1, 0.5 at rest for the sticks) and buttons as pad.N.button.K (0 or 1). A pad
// unplugged goes back to rest. The gallery only: headless runs never touch GLFW.
#include "live/source_bank.h"

#include <bitset>

namespace vitrine::host {

class Gamepads {
 public:
  void read(live::SourceBank& sources);  // once a step, on the main thread

 private:
  std::bitset<16> connected_;
};

}  // namespace vitrine::host
