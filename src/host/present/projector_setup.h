#pragma once
// Projector setup (F7 in the gallery): the main output's corner pin, dragged on the picture itself. While
// it is on, the mouse moves corners instead of playing the scene: a press near a corner takes it and
// dragging moves it (onto an edge of the output when within kSnapPixels of it); the arrow keys nudge the
// corner last taken by a pixel (ten with Shift); Backspace puts all four back where an unwarped picture
// has them; Enter keeps the pin, Esc puts back the one setup started with. A move that would make the picture's outline cross
// itself or fold is not taken, so the pin can always be shown. With more outputs, F7 keeps this one's pin
// and goes on to the next (the main window then shows what that output shows, to drag on). Pure logic
// on the warp; the gallery draws the handles and keeps the result.
#include "host/pointer.h"
#include "maths/output_warp.h"

#include <optional>
#include <string_view>

namespace vitrine::host {

class ProjectorSetup {
 public:
  static constexpr float kReachPixels = 24.0f;  // how near a press must be to take a corner
  // A corner dragged this near an edge of the output lands on it: the last pixel is not the edge.
  static constexpr float kSnapPixels = 2.0f;

  bool active() const { return active_; }
  void start(const maths::OutputWarp& warp);

  // The mouse this frame, over an output of pointer.framebuffer pixels; moves the corner held.
  void pointer(const Pointer& pointer, maths::OutputWarp& warp);

  enum class Key { Ignored, Used, Kept, Undone, Next };
  // A key pressed (a GLFW key code), `shift` held, over an output of `output` pixels. Kept and Undone end
  // setup; Undone has put the warp back. Next (F7) keeps this pin: the caller start()s the next output's.
  Key key(int key, bool shift, VkExtent2D output, maths::OutputWarp& warp);

  // The handles over the output (Dear ImGui, between the overlay's beginFrame and its record): the
  // picture's outline, its four corners (the one the arrows move larger) and what the keys do.
  // `name`: the output being set up, `outputs`: how many there are (F7's hint shows with more than one).
  void draw(const maths::OutputWarp& warp, VkExtent2D output, std::string_view name, size_t outputs) const;

  std::optional<int> held() const { return held_; }
  int selected() const { return selected_; }

 private:
  // Moves corner `corner` to `to` (output 0..1) when the pin stays showable.
  static bool move(maths::OutputWarp& warp, int corner, glm::vec2 to);
  // The pointer's pixel as output 0..1, on the edge when within kSnapPixels of it.
  static glm::vec2 snapped(glm::vec2 pixels, glm::vec2 size);
  bool active_ = false;
  maths::OutputWarp before_;
  std::optional<int> held_;  // the corner being dragged
  int selected_ = 0;         // the corner the arrows move
};

}  // namespace vitrine::host
