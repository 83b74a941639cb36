#include "host/present/window.h"

#include "gpu/check.h"
#include "host/present/screen_area.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <utility>

namespace vitrine::host {
namespace {

std::string glfwReason() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "no reason given";
}

Window& owner(GLFWwindow* window) { return *static_cast<Window*>(glfwGetWindowUserPointer(window)); }

std::vector<GLFWmonitor*> monitors() {
  int count = 0;
  GLFWmonitor** list = glfwGetMonitors(&count);
  return {list, list + std::max(count, 0)};
}

// Where a monitor lies on the desktop, in pixels (its current mode's size).
ScreenArea areaOf(GLFWmonitor* monitor) {
  ScreenArea area;
  glfwGetMonitorPos(monitor, &area.x, &area.y);
  if (const GLFWvidmode* mode = glfwGetVideoMode(monitor)) area.width = mode->width, area.height = mode->height;
  return area;
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

std::string describeMonitors() {
  std::string text;
  const std::vector<GLFWmonitor*> all = monitors();
  for (size_t i = 0; i < all.size(); ++i) {
    int x = 0, y = 0;
    glfwGetMonitorPos(all[i], &x, &y);
    const GLFWvidmode* mode = glfwGetVideoMode(all[i]);
    text += fmt::format("{} {} {}  {}x{} at {},{}  {} Hz\n", all[i] == glfwGetPrimaryMonitor() ? '*' : ' ', i,
                        glfwGetMonitorName(all[i]), mode ? mode->width : 0, mode ? mode->height : 0, x, y,
                        mode ? mode->refreshRate : 0);
  }
  return text.empty() ? "(no monitors)\n" : text;
}

}  // namespace

// The monitor `wanted` names: its index, or a part of its name (any case); empty: the primary.
GLFWmonitor* findMonitor(std::string_view wanted) {
  if (wanted.empty()) return glfwGetPrimaryMonitor();
  const std::vector<GLFWmonitor*> all = monitors();
  size_t index = 0;
  const auto [end, ec] = std::from_chars(wanted.data(), wanted.data() + wanted.size(), index);
  if (ec == std::errc() && end == wanted.data() + wanted.size()) {
    if (index < all.size()) return all[index];
  } else {
    for (GLFWmonitor* monitor : all)
      if (lowercase(std::string(glfwGetMonitorName(monitor))).find(lowercase(std::string(wanted))) != std::string::npos) return monitor;
  }
  throw Error(fmt::format("No monitor '{}'; there are:\n{}", wanted, describeMonitors()));
}

GLFWmonitor* monitorShowing(GLFWwindow* window) {
  if (GLFWmonitor* own = glfwGetWindowMonitor(window)) return own;
  ScreenArea area;
  glfwGetWindowPos(window, &area.x, &area.y);
  glfwGetWindowSize(window, &area.width, &area.height);
  const std::vector<GLFWmonitor*> all = monitors();
  std::vector<ScreenArea> areas;
  for (GLFWmonitor* monitor : all) areas.push_back(areaOf(monitor));
  const std::optional<size_t> shown = mostShared(area, areas);
  return shown ? all[*shown] : glfwGetPrimaryMonitor();
}

Surface::Surface(Surface&& other) noexcept
    : instance_(other.instance_), surface_(std::exchange(other.surface_, VK_NULL_HANDLE)) {}

Surface::~Surface() {
  if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
}

Window::Glfw::Glfw() {
  if (!glfwInit())
    throw Error(fmt::format("Cannot open a window ({}); run vitrine --headless to render without a display.",
                            glfwReason()));
}

Window::Glfw::~Glfw() { glfwTerminate(); }

std::string Window::listMonitors() {
  const Glfw glfw;  // no window is open in this mode
  return describeMonitors();
}

Window::Window(VkExtent2D size, bool fullscreen, std::string_view monitor, bool span) : monitor_(findMonitor(monitor)) {
  if (!glfwVulkanSupported())
    throw Error("GLFW found no Vulkan loader for windows; install libvulkan1, or use --headless.");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  int left = 0, top = 0, right = 0, bottom = 0;  // every monitor's area, for --span
  for (GLFWmonitor* each : monitors()) {
    const ScreenArea area = areaOf(each);
    left = std::min(left, area.x), top = std::min(top, area.y);
    right = std::max(right, area.x + area.width), bottom = std::max(bottom, area.y + area.height);
  }
  if (span) {
    glfwWindowHint(GLFW_DECORATED, GLFW_FALSE);
    size = {uint32_t(std::max(right - left, 1)), uint32_t(std::max(bottom - top, 1))};
  }
  window_ = glfwCreateWindow(int(size.width), int(size.height), "Vitrine", nullptr, nullptr);
  glfwDefaultWindowHints();
  if (!window_) throw Error(fmt::format("Cannot create the gallery window: {}.", glfwReason()));
  // Set before Dear ImGui installs its callbacks, which then forward every event here as well.
  glfwSetWindowUserPointer(window_, this);
  glfwSetKeyCallback(window_, &Window::onKey);
  glfwSetMouseButtonCallback(window_, &Window::onMouseButton);
  glfwSetScrollCallback(window_, &Window::onScroll);
  glfwSetDropCallback(window_, &Window::onDrop);
  if (span) glfwSetWindowPos(window_, left, top);
  if (monitor_ && !monitor.empty()) {  // windowed, centred on the chosen monitor
    int x = 0, y = 0, width = 0, height = 0;
    glfwGetMonitorWorkarea(monitor_, &x, &y, &width, &height);
    glfwSetWindowPos(window_, x + std::max(0, (width - int(size.width)) / 2), y + std::max(0, (height - int(size.height)) / 2));
  }
  if (fullscreen && !span) toggleFullscreen();  // a span is already the whole desktop, kiosk or not
}

Window::~Window() { glfwDestroyWindow(window_); }

std::vector<const char*> Window::vulkanExtensions() const {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw Error(fmt::format("This display cannot show Vulkan windows: {}.", glfwReason()));
  return {names, names + count};
}

Surface Window::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface;
  VK_CHECK(glfwCreateWindowSurface(instance, window_, nullptr, &surface));
  return Surface(instance, surface);
}

void Window::pollEvents() { glfwPollEvents(); }

bool Window::hidden() const {
  const VkExtent2D size = framebufferSize();
  return size.width == 0 || size.height == 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED);
}

void Window::waitForEvents(double seconds) const { glfwWaitEventsTimeout(seconds); }

bool Window::shouldClose() const { return glfwWindowShouldClose(window_); }

void Window::close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

VkExtent2D Window::framebufferSize() const {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  return {uint32_t(width), uint32_t(height)};
}

void Window::setCursorHidden(bool hidden) {
  glfwSetInputMode(window_, GLFW_CURSOR, hidden ? GLFW_CURSOR_HIDDEN : GLFW_CURSOR_NORMAL);
}

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void Window::toggleFullscreen() {
  if (glfwGetWindowMonitor(window_)) {
    glfwSetWindowMonitor(window_, nullptr, windowedX_, windowedY_, windowedWidth_, windowedHeight_, GLFW_DONT_CARE);
    return;
  }
  GLFWmonitor* monitor = monitor_ ? monitor_ : glfwGetPrimaryMonitor();
  if (!monitor) return;
  glfwGetWindowPos(window_, &windowedX_, &windowedY_);
  glfwGetWindowSize(window_, &windowedWidth_, &windowedHeight_);
  const GLFWvidmode* mode = glfwGetVideoMode(monitor);
  glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

std::string Window::monitorName() const {
  GLFWmonitor* monitor = monitor_ ? monitor_ : glfwGetPrimaryMonitor();
  return monitor ? glfwGetMonitorName(monitor) : "";
}

std::vector<int> Window::takeKeys() { return std::exchange(keys_, {}); }

std::vector<std::string> Window::takeDrops() { return std::exchange(drops_, {}); }

// The cursor in framebuffer pixels: GLFW reports screen coordinates, and on HiDPI displays a
// framebuffer pixel is smaller.
glm::vec2 Window::cursorPixels() const {
  double x = 0.0, y = 0.0;
  int width = 0, height = 0;
  glfwGetCursorPos(window_, &x, &y);
  glfwGetWindowSize(window_, &width, &height);
  const VkExtent2D framebuffer = framebufferSize();
  glm::vec2 scale(1.0f);
  if (width > 0 && height > 0) scale = glm::vec2(framebuffer.width, framebuffer.height) / glm::vec2(width, height);
  return glm::vec2(float(x), float(y)) * scale;
}

Pointer Window::takePointer() {
  double x = 0.0, y = 0.0;
  int width = 0, height = 0;
  glfwGetCursorPos(window_, &x, &y);
  glfwGetWindowSize(window_, &width, &height);
  const bool inside = glfwGetWindowAttrib(window_, GLFW_HOVERED) && x >= 0.0 && y >= 0.0 && x < width && y < height;
  return Pointer{cursorPixels(),
                 framebufferSize(),
                 glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS,
                 std::exchange(leftPressed_, false),
                 std::exchange(wheel_, 0.0f),
                 inside,
                 std::exchange(leftReleasedAt_, std::nullopt)};
}

void Window::takeKeysOf(GLFWwindow* other) {
  glfwSetWindowUserPointer(other, this);
  glfwSetKeyCallback(other, &Window::onKey);
}

void Window::onKey(GLFWwindow* window, int key, int, int action, int) {
  if (key == GLFW_KEY_UNKNOWN) return;
  Window& self = owner(window);
  if (action == GLFW_PRESS) {
    self.keys_.push_back(key);
    if (std::find(self.held_.begin(), self.held_.end(), key) == self.held_.end()) self.held_.push_back(key);
  }
  if (action == GLFW_RELEASE) std::erase(self.held_, key);
}

void Window::onDrop(GLFWwindow* window, int count, const char** paths) {
  for (int i = 0; i < count; ++i) owner(window).drops_.emplace_back(paths[i]);
}

void Window::onMouseButton(GLFWwindow* window, int button, int action, int) {
  if (button != GLFW_MOUSE_BUTTON_LEFT) return;
  Window& self = owner(window);
  if (action == GLFW_PRESS) self.leftPressed_ = true;
  if (action == GLFW_RELEASE) self.leftReleasedAt_ = self.cursorPixels();  // events arrive in order: where it let go
}

void Window::onScroll(GLFWwindow* window, double, double y) { owner(window).wheel_ += float(y); }

}  // namespace vitrine::host
