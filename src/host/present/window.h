#pragma once
// The gallery's OS window, through GLFW: its Vulkan surface, fullscreen, and the input that arrives
// between frames (keys, clicks, scrolling), held until the frame loop takes it.
#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "host/pointer.h"

struct GLFWwindow;
struct GLFWmonitor;

namespace vitrine::host {

// Owns a VkSurfaceKHR. Not a gpu::Unique: a surface is destroyed through the instance, not a device.
class Surface {
 public:
  Surface(VkInstance instance, VkSurfaceKHR surface) : instance_(instance), surface_(surface) {}
  Surface(Surface&& other) noexcept;
  Surface& operator=(Surface&&) = delete;
  Surface(const Surface&) = delete;
  ~Surface();
  VkSurfaceKHR handle() const { return surface_; }

 private:
  VkInstance instance_;
  VkSurfaceKHR surface_;
};

// The monitor `wanted` names: its index in --list-monitors, or a part of its name (any case); empty:
// the primary. GLFW must be up (a Window open). Throws vitrine::Error listing the monitors there are.
GLFWmonitor* findMonitor(std::string_view wanted);
// The monitor that shows `window`: its own when fullscreen, else the one holding most of it
// (screen_area.h); the primary when it lies off every one.
GLFWmonitor* monitorShowing(GLFWwindow* window);

class Window {
 public:
  // Throws vitrine::Error, naming the reason, when there is no display to open a window on, or no
  // monitor `monitor` names (an index from --list-monitors, or part of a name; empty: the primary).
  // `span`: one window without a frame over every monitor's area (a projector pair as one desktop).
  Window(VkExtent2D size, bool fullscreen, std::string_view monitor = {}, bool span = false);
  // The monitors, one a line: index, name, position and mode, the primary marked (--list-monitors).
  static std::string listMonitors();
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  std::vector<const char*> vulkanExtensions() const;  // what the instance needs for a surface
  Surface createSurface(VkInstance instance) const;

  void pollEvents();
  bool hidden() const;           // minimised, or a framebuffer with no pixels
  // Sleeps in the event queue for at most `seconds`: a minimised gallery costs next to no CPU.
  void waitForEvents(double seconds) const;
  bool shouldClose() const;
  void close();
  VkExtent2D framebufferSize() const;
  void setTitle(const std::string& title);
  void setCursorHidden(bool hidden);  // kiosk mode: no arrow over the pieces
  void toggleFullscreen();  // on the chosen monitor; back to the windowed position and size
  std::string monitorName() const;  // the chosen monitor's, for the settings it keeps per output

  // Keys pressed while `other` (an output window: output_window.h) has the focus count as this
  // window's, so a projector's window never swallows Esc, F7 or a scene's number.
  void takeKeysOf(GLFWwindow* other);
  std::vector<int> takeKeys();  // GLFW key codes pressed since the last take, in order
  const std::vector<int>& keysHeld() const { return held_; }  // GLFW key codes down now
  std::vector<std::string> takeDrops();  // paths of files dropped onto the window since the last take
  Pointer takePointer();

 private:
  struct Glfw {  // first member: glfwTerminate runs even when the constructor throws after glfwInit
    Glfw();
    ~Glfw();
  } glfw_;
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
  static void onScroll(GLFWwindow* window, double x, double y);
  static void onDrop(GLFWwindow* window, int count, const char** paths);
  glm::vec2 cursorPixels() const;  // framebuffer pixels

  GLFWwindow* window_ = nullptr;
  GLFWmonitor* monitor_ = nullptr;  // where the window opens and goes fullscreen
  int windowedX_ = 0, windowedY_ = 0, windowedWidth_ = 0, windowedHeight_ = 0;
  std::vector<int> keys_;
  std::vector<int> held_;
  std::vector<std::string> drops_;
  bool leftPressed_ = false;
  std::optional<glm::vec2> leftReleasedAt_;
  float wheel_ = 0.0f;
};

}  // namespace vitrine::host
