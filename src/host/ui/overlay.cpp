#include "host/ui/overlay.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "gpu/check.h"
#include "host/ui/font_check.h"
#include "host/ui/menu.h"
#include "host/present/swapchain.h"
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_freetype.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

namespace vitrine::host {
namespace {

void checkBackendResult(VkResult result) {
  if (result < 0) gpu::throwVkError(result, "Dear ImGui Vulkan backend", __FILE__, __LINE__);
}

gpu::Unique<VkDescriptorPool> createPool(const gpu::Device& device) {
  // The backend allocates exactly one set: the font atlas.
  const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.maxSets = 1;
  info.poolSizeCount = 1;
  info.pPoolSizes = &size;
  VkDescriptorPool pool;
  VK_CHECK(vkCreateDescriptorPool(device, &info, nullptr, &pool));
  device.name(pool, VK_OBJECT_TYPE_DESCRIPTOR_POOL, "overlay descriptors");
  return gpu::Unique<VkDescriptorPool>(device, pool);
}

gpu::Unique<VkRenderPass> createRenderPass(const gpu::Device& device, VkFormat format) {
  VkAttachmentDescription attachment{};
  attachment.format = format;
  attachment.samples = VK_SAMPLE_COUNT_1_BIT;
  attachment.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // the scene is already there
  attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachment.initialLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  attachment.finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR;
  const VkAttachmentReference color{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &color;
  // Restates the scene renderer's last barrier, so the pass is correct on its own. The transition to
  // PRESENT_SRC at the end needs nothing more: the render-finished semaphore waits for all commands.
  VkSubpassDependency after{};
  after.srcSubpass = VK_SUBPASS_EXTERNAL;
  after.dstSubpass = 0;
  after.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  after.dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  after.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  VkRenderPassCreateInfo info{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  info.attachmentCount = 1;
  info.pAttachments = &attachment;
  info.subpassCount = 1;
  info.pSubpasses = &subpass;
  info.dependencyCount = 1;
  info.pDependencies = &after;
  VkRenderPass renderPass;
  VK_CHECK(vkCreateRenderPass(device, &info, nullptr, &renderPass));
  device.name(renderPass, VK_OBJECT_TYPE_RENDER_PASS, "overlay");
  return gpu::Unique<VkRenderPass>(device, renderPass);
}

// Dear ImGui asserts when its font builder fails, so a file FreeType cannot use (truncated, or a
// FreeType built without woff2 support) is found out here, left out and named in `problems`.
ImFont* addFont(const std::optional<std::filesystem::path>& path, float pixels, std::vector<std::string>& problems) {
  if (!path) return nullptr;
  if (const std::string problem = fontProblem(*path); !problem.empty()) {
    problems.push_back(fmt::format("font {} is unusable (FreeType: {}): using Dear ImGui's built-in font",
                                   path->string(), problem));
    return nullptr;
  }
  return ImGui::GetIO().Fonts->AddFontFromFileTTF(path->c_str(), pixels);
}

// Dear ImGui 1.86 samples keys as up/down state once a frame: at a few frames a second, a key pressed
// and released between two frames (Enter typed into a field) is never seen down, so the field never
// commits. This hook sits in front of the backend's key callback and keeps such a key down until the
// next frame has begun, when endOfKeyFrame() lets it go. (1.87 replaced this with an event queue.)
struct KeyHold {
  GLFWkeyfun backend = nullptr;
  std::vector<int> pressed;  // since the frame began
  std::vector<int> release;  // released too: up after the next NewFrame
};
KeyHold keyHold;

void holdKeyForAFrame(GLFWwindow* window, int key, int scancode, int action, int mods) {
  if (keyHold.backend) keyHold.backend(window, key, scancode, action, mods);
  ImGuiIO& io = ImGui::GetIO();
  if (key < 0 || key >= int(IM_ARRAYSIZE(io.KeysDown))) return;
  if (action == GLFW_PRESS) keyHold.pressed.push_back(key);
  if (action == GLFW_RELEASE && std::find(keyHold.pressed.begin(), keyHold.pressed.end(), key) != keyHold.pressed.end()) {
    io.KeysDown[key] = true;
    keyHold.release.push_back(key);
  }
}

void endOfKeyFrame() {
  ImGuiIO& io = ImGui::GetIO();
  for (int key : keyHold.release) io.KeysDown[key] = false;
  keyHold.release.clear();
  keyHold.pressed.clear();
}

}  // namespace

Overlay::Context::Context(GLFWwindow* window, const Fonts& fonts, std::filesystem::path layout, bool forgetLayout)
    : layoutFile(layout.string()) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  // Never an imgui.ini dropped into the user's working folder: the layout lives beside the settings.
  io.IniFilename = nullptr;
  if (!layoutFile.empty()) {
    std::error_code ignored;
    if (forgetLayout) std::filesystem::remove(layout, ignored);
    std::filesystem::create_directories(layout.parent_path(), ignored);
    io.IniFilename = layoutFile.c_str();
  }
  io.Fonts->FontBuilderIO = ImGuiFreeType::GetBuilderForFreeType();  // reads the woff2 files
  if (!addFont(fonts.body, 17.0f, fontProblems)) io.Fonts->AddFontDefault();  // the first font is the default
  titles = addFont(fonts.titles, 21.0f, fontProblems);
  ImGui::StyleColorsDark();
  // Pop-ups (a combo's list) and the help card opaque: over a bright scene the default's see-through
  // backgrounds leave their text unreadable.
  ImGui::GetStyle().Colors[ImGuiCol_PopupBg].w = 1.0f;
  // Installs its callbacks on top of the window's own, forwarding every event to them.
  if (!ImGui_ImplGlfw_InitForVulkan(window, true)) {
    ImGui::DestroyContext();
    throw Error("Dear ImGui could not attach to the gallery window.");
  }
  keyHold = KeyHold{glfwSetKeyCallback(window, &holdKeyForAFrame)};
}

Overlay::Context::~Context() {
  keyHold = {};
  ImGui_ImplGlfw_Shutdown();  // puts back the window's own callbacks
  ImGui::DestroyContext();
}

Overlay::Renderer::Renderer(const gpu::Device& device, VkDescriptorPool pool, VkRenderPass renderPass,
                            uint32_t framesInFlight) {
  ImGui_ImplVulkan_InitInfo info{};
  info.Instance = device.instance();
  info.PhysicalDevice = device.physical();
  info.Device = device;
  info.QueueFamily = device.queueFamily();
  info.Queue = device.queue();
  info.DescriptorPool = pool;
  // The backend rewrites one vertex buffer per frame from a ring of ImageCount; frames in flight is
  // what keeps a buffer from being rewritten while the GPU still reads it, not the swapchain's count.
  info.MinImageCount = framesInFlight;
  info.ImageCount = framesInFlight;
  info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
  info.CheckVkResultFn = &checkBackendResult;
  if (!ImGui_ImplVulkan_Init(&info, renderPass)) throw Error("Dear ImGui's Vulkan backend failed to start.");
}

Overlay::Renderer::~Renderer() { ImGui_ImplVulkan_Shutdown(); }

Overlay::Overlay(const gpu::Device& device, GLFWwindow* window, VkFormat format, uint32_t framesInFlight,
                 const Fonts& fonts, std::filesystem::path layoutFile, bool forgetLayout)
    : device_(device),
      pool_(createPool(device)),
      renderPass_(createRenderPass(device, format)),
      context_(window, fonts, std::move(layoutFile), forgetLayout),
      renderer_(device, pool_, renderPass_, framesInFlight) {
  device.submitNow([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
  ImGui_ImplVulkan_DestroyFontUploadObjects();
}

void Overlay::attach(const Swapchain& swapchain) {
  if (!framebuffers_.empty()) device_.retire(std::move(framebuffers_));  // frames in flight still use them
  framebuffers_.clear();
  extent_ = swapchain.extent();
  for (uint32_t i = 0; i < swapchain.imageCount(); ++i) {
    const VkImageView view = swapchain.view(i);
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = extent_.width;
    info.height = extent_.height;
    info.layers = 1;
    VkFramebuffer framebuffer;
    VK_CHECK(vkCreateFramebuffer(device_, &info, nullptr, &framebuffer));
    device_.name(framebuffer, VK_OBJECT_TYPE_FRAMEBUFFER, fmt::format("overlay framebuffer {}", i));
    framebuffers_.emplace_back(device_, framebuffer);
  }
}

void Overlay::beginFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();  // sees the keys held for it
  endOfKeyFrame();
}

void Overlay::record(VkCommandBuffer cmd, uint32_t image, gpu::PassTimer* timer) {
  ImGui::Render();
  gpu::Pass pass(device_, timer, cmd, "overlay");
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = renderPass_;
  begin.framebuffer = framebuffers_[image];
  begin.renderArea = {{0, 0}, extent_};
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vkCmdEndRenderPass(cmd);
}

bool Overlay::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }

bool Overlay::wantsText() const { return ImGui::GetIO().WantTextInput; }

bool Overlay::wantsKeyboard() const { return menuHasKeyboard(); }

}  // namespace vitrine::host
