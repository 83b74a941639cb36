#include "host/gallery/gamepads.h"

#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <cstdio>

namespace vitrine::host {
namespace {

// GLFW's axes run -1..1; the triggers (4, 5) rest at -1, the sticks at 0.
void setPad(live::SourceBank& sources, int pad, const GLFWgamepadstate* state) {
  for (int axis = 0; axis <= GLFW_GAMEPAD_AXIS_LAST; ++axis) {
    const float rest = axis >= GLFW_GAMEPAD_AXIS_LEFT_TRIGGER ? -1.0f : 0.0f;
    sources.set(fmt::format("pad.{}.axis.{}", pad, axis), ((state ? state->axes[axis] : rest) + 1.0f) * 0.5f);
  }
  for (int button = 0; button <= GLFW_GAMEPAD_BUTTON_LAST; ++button)
    sources.set(fmt::format("pad.{}.button.{}", pad, button), state && state->buttons[button] == GLFW_PRESS ? 1.0f : 0.0f);
}

}  // namespace

void Gamepads::read(live::SourceBank& sources) {
  for (int pad = 0; pad <= GLFW_JOYSTICK_LAST && pad < int(connected_.size()); ++pad) {
    GLFWgamepadstate state;
    const bool there = glfwJoystickIsGamepad(pad) && glfwGetGamepadState(pad, &state);
    if (there != connected_[size_t(pad)]) {
      const char* name = there ? glfwGetGamepadName(pad) : nullptr;
      std::printf("vitrine: gamepad %d %s%s\n", pad, there ? "connected: " : "disconnected", name ? name : "");
      connected_[size_t(pad)] = there;
      if (!there) setPad(sources, pad, nullptr);
    }
    if (there) setPad(sources, pad, &state);
  }
}

}  // namespace vitrine::host
