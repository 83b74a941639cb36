#include "host/present/projector_setup.h"

#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <imgui.h>

namespace vitrine::host {

void ProjectorSetup::start(const maths::OutputWarp& warp) {
  active_ = true;
  before_ = warp;
  held_.reset();
  selected_ = 0;
}

bool ProjectorSetup::move(maths::OutputWarp& warp, int corner, glm::vec2 to) {
  maths::OutputWarp moved = warp;
  moved.corners[size_t(corner)] = glm::clamp(to, glm::vec2(-0.5f), glm::vec2(1.5f));  // off the output a little at most
  if (!maths::checkWarp(moved).empty()) return false;
  warp = moved;
  return true;
}

void ProjectorSetup::pointer(const Pointer& pointer, maths::OutputWarp& warp) {
  if (!active_ || pointer.framebuffer.width == 0 || pointer.framebuffer.height == 0) return;
  const glm::vec2 size(float(pointer.framebuffer.width), float(pointer.framebuffer.height));
  if (pointer.leftPressed && pointer.inside) {
    float nearest = kReachPixels;
    for (int i = 0; i < 4; ++i)
      if (const float d = glm::distance(warp.corners[size_t(i)] * size, pointer.pixels); d <= nearest)
        nearest = d, held_ = i, selected_ = i;
  }
  if (held_ && !pointer.leftHeld) {  // let go: where it was let go, this frame's last moves included
    if (pointer.releasedAt) move(warp, *held_, snapped(*pointer.releasedAt, size));
    held_.reset();
  }
  if (held_) move(warp, *held_, snapped(pointer.pixels, size));
}

glm::vec2 ProjectorSetup::snapped(glm::vec2 pixels, glm::vec2 size) {
  glm::vec2 at = pixels / size;
  for (int axis = 0; axis < 2; ++axis) {
    if (pixels[axis] <= kSnapPixels) at[axis] = 0.0f;
    if (pixels[axis] >= size[axis] - 1.0f - kSnapPixels) at[axis] = 1.0f;
  }
  return at;
}

ProjectorSetup::Key ProjectorSetup::key(int key, bool shift, VkExtent2D output, maths::OutputWarp& warp) {
  if (!active_) return Key::Ignored;
  const glm::vec2 pixel = glm::vec2(shift ? 10.0f : 1.0f) / glm::vec2(float(output.width), float(output.height));
  glm::vec2 step(0.0f);
  switch (key) {
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER: active_ = false; return Key::Kept;
    case GLFW_KEY_ESCAPE:
      warp = before_;
      active_ = false;
      return Key::Undone;
    case GLFW_KEY_F7: active_ = false; return Key::Next;
    case GLFW_KEY_TAB: selected_ = (selected_ + 1) % 4; return Key::Used;
    case GLFW_KEY_BACKSPACE: warp.corners = maths::OutputWarp{}.corners; return Key::Used;
    case GLFW_KEY_LEFT: step.x = -pixel.x; break;
    case GLFW_KEY_RIGHT: step.x = pixel.x; break;
    case GLFW_KEY_UP: step.y = -pixel.y; break;
    case GLFW_KEY_DOWN: step.y = pixel.y; break;
    default: return Key::Ignored;
  }
  move(warp, selected_, warp.corners[size_t(selected_)] + step);
  return Key::Used;
}

void ProjectorSetup::draw(const maths::OutputWarp& warp, VkExtent2D output, std::string_view name, size_t outputs) const {
  if (!active_) return;
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImU32 line = IM_COL32(255, 214, 120, 230), shade = IM_COL32(0, 0, 0, 160);
  ImVec2 points[4];
  for (size_t i = 0; i < 4; ++i)
    points[i] = ImVec2(warp.corners[i].x * float(output.width), warp.corners[i].y * float(output.height));
  draw->AddPolyline(points, 4, line, ImDrawFlags_Closed, 2.0f);
  for (int i = 0; i < 4; ++i) {
    const float radius = i == selected_ ? 14.0f : 9.0f;
    draw->AddCircleFilled(points[i], radius + 2.0f, shade);
    draw->AddCircle(points[i], radius, line, 0, i == held_ ? 4.0f : 2.0f);
  }
  const std::string text = fmt::format(
      "PROJECTOR SETUP: {}\ndrag each corner onto the screen's corner\narrows nudge it (Shift: 10 px), "
      "Tab: the next\nBackspace: the unwarped corners\nEnter keeps the pin, Esc undoes it{}",
      name, outputs > 1 ? "\nF7 keeps it and sets up the next output" : "");
  const char* help = text.c_str();
  const ImVec2 size = ImGui::CalcTextSize(help);
  const ImVec2 at((float(output.width) - size.x) * 0.5f, float(output.height) * 0.5f - size.y);
  draw->AddRectFilled(ImVec2(at.x - 8, at.y - 6), ImVec2(at.x + size.x + 8, at.y + size.y + 6), shade, 4.0f);
  draw->AddText(at, line, help);
}

}  // namespace vitrine::host
