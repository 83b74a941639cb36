#include "host/present/output_window.h"

#include "core/bounded_file.h"
#include "core/error.h"
#include "gpu/check.h"
#include "gpu/sync_objects.h"
#include "host/present/output_warp_file.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>


namespace vitrine::host {

constexpr uintmax_t kMaxOutputsFileBytes = 1 << 20;  // an output is a line of JSON

std::vector<OutputPlacement> readOutputs(const std::filesystem::path& file) {
  std::string text;
  try {
    text = readBoundedFile(file, kMaxOutputsFileBytes);
  } catch (const FileRefused& refused) {
    throw Error(fmt::format("Cannot read the outputs {}: {}", file.string(), refused.why));
  }
  const nlohmann::json list = nlohmann::json::parse(text, nullptr, false);
  if (!list.is_array()) throw Error(fmt::format("{}: the outputs are a JSON array of objects", file.string()));
  std::vector<OutputPlacement> outputs;
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string where = fmt::format("{}, output {}", file.string(), i + 1);
    const nlohmann::json& entry = list[i];
    if (!entry.is_object()) throw Error(fmt::format("{}: an output is an object", where));
    OutputPlacement output;
    for (const auto& [key, value] : entry.items()) {
      if (key == "monitor" && (value.is_string() || value.is_number_unsigned()))
        output.monitor = value.is_string() ? value.get<std::string>() : std::to_string(value.get<unsigned>());
      else if (key == "window" && value.is_array() && value.size() == 4 &&
               std::all_of(value.begin(), value.end(), [](const auto& v) { return v.is_number_integer(); }))
        output.window = std::array<int, 4>{value[0], value[1], value[2], value[3]};
      else if (key == "pipewire" && value.is_string() && !value.get<std::string>().empty())
        output.pipewire = value.get<std::string>();
      else if (key == "size" && value.is_array() && value.size() == 2 &&
               std::all_of(value.begin(), value.end(), [](const auto& v) { return v.is_number_integer(); }))
        output.size = std::array<int, 2>{value[0], value[1]};
      else if (key == "warp")
        output.warp = outputWarpFromJson(value, where);
      else if (key == "name" && value.is_string() && !value.get<std::string>().empty())
        output.name = value.get<std::string>();
      else
        throw Error(fmt::format("{}: \"{}\" is not one of monitor (an index or a name), window ([x, y, width, "
                                "height]), pipewire (a node's name), size ([width, height]), warp and name (a text)",
                                where, key));
    }
    if (output.name.empty())
      output.name = !output.monitor.empty()  ? output.monitor
                    : !output.pipewire.empty() ? output.pipewire
                                               : fmt::format("output {}", i + 1);
    if (output.name == "main") throw Error(fmt::format("{}: \"main\" is the main window's name", where));
    for (const OutputPlacement& other : outputs)
      if (other.name == output.name)
        throw Error(fmt::format("{}: another output is named \"{}\" (give each a \"name\")", where, output.name));
    if (output.window && ((*output.window)[2] <= 0 || (*output.window)[3] <= 0))
      throw Error(fmt::format("{}: a window has a width and a height above 0", where));
    if (int(output.window.has_value()) + int(!output.monitor.empty()) + int(!output.pipewire.empty()) > 1)
      throw Error(fmt::format("{}: an output is fullscreen on a monitor, a window at a place or a PipeWire node, "
                              "one of them", where));
    if (output.size && output.pipewire.empty())
      throw Error(fmt::format("{}: a size is a PipeWire node's; a window's is in \"window\"", where));
    if (output.size && ((*output.size)[0] <= 0 || (*output.size)[1] <= 0))
      throw Error(fmt::format("{}: a size has a width and a height above 0", where));
    outputs.push_back(std::move(output));
  }
  if (outputs.size() > 7) throw Error(fmt::format("{}: at most 7 outputs besides the main window", file.string()));
  return outputs;
}

OutputWindow::OutputWindow(const gpu::Instance& instance, const gpu::Device& device, const OutputPlacement& placement,
                           bool vsync, uint32_t framesInFlight, int index)
    : Output(placement.name, placement.warp.value_or(maths::OutputWarp{})) {
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_DECORATED, GLFW_FALSE);  // a projector shows the picture, not a title bar
  glfwWindowHint(GLFW_FOCUSED, GLFW_FALSE);
  glfwWindowHint(GLFW_FOCUS_ON_SHOW, GLFW_FALSE);
  const std::string title = fmt::format("Vitrine output {}", index);
  if (placement.window) {
    const auto [x, y, width, height] = *placement.window;
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window_) glfwSetWindowPos(window_, x, y);
  } else {
    GLFWmonitor* monitor = findMonitor(placement.monitor);
    const GLFWvidmode* mode = glfwGetVideoMode(monitor);
    window_ = glfwCreateWindow(mode->width, mode->height, title.c_str(), monitor, nullptr);
  }
  glfwDefaultWindowHints();
  if (!window_) throw Error(fmt::format("Cannot open output {}'s window", index));
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VK_CHECK(glfwCreateWindowSurface(instance.handle(), window_, nullptr, &surface));
  surface_.emplace(instance.handle(), surface);
  VkBool32 presents = VK_FALSE;
  VK_CHECK(vkGetPhysicalDeviceSurfaceSupportKHR(device.physical(), device.queueFamily(), surface, &presents));
  if (!presents)
    throw Error(fmt::format("{} cannot present to output {}'s window", device.properties().deviceName, index));
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  const VkExtent2D framebuffer{uint32_t(std::max(width, 1)), uint32_t(std::max(height, 1))};
  swapchain_.emplace(device, surface, window_, framebuffer, vsync);
  for (uint32_t slot = 0; slot < framesInFlight; ++slot)
    acquired_.push_back(gpu::createSemaphore(device, fmt::format("output {} image acquired {}", index, slot)));
}

OutputWindow::~OutputWindow() {
  swapchain_.reset();  // its images before the surface, the surface before the window
  surface_.reset();
  if (window_) glfwDestroyWindow(window_);
}

bool OutputWindow::acquire(uint32_t slot, bool vsync) {
  image_.reset();
  int width = 0, height = 0;
  glfwGetFramebufferSize(window_, &width, &height);
  if (width <= 0 || height <= 0 || glfwGetWindowAttrib(window_, GLFW_ICONIFIED)) return false;
  const VkExtent2D size{uint32_t(width), uint32_t(height)};
  if (!swapchain_->fits(size, vsync)) swapchain_->recreate(size, vsync);
  image_ = swapchain_->acquire(acquired_[slot]);
  return image_.has_value();
}

BlitDestination OutputWindow::destination(VkPipelineStageFlags2 acquireStage) const {
  const bool compute = swapchain_->computeWrites();
  return {swapchain_->image(*image_), swapchain_->extent(), {acquireStage, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED},
          gpu::use::Present, compute ? swapchain_->view(*image_) : VK_NULL_HANDLE, compute, &warp()};
}

void OutputWindow::present() {
  if (image_) swapchain_->present(*std::exchange(image_, std::nullopt));
}

}  // namespace vitrine::host
