#pragma once
// What a scene is to the host: a name, a title, a number key and a lifecycle. Scenes see the device,
// the program library and the frame they are asked to draw; nothing else of the host.
#include "gpu/pass_timer.h"
#include "gpu/program.h"

#include <glm/vec2.hpp>

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine {

struct CursorInput {
  glm::vec2 pixels{0.0f};      // framebuffer pixels, origin top-left (HiDPI-correct)
  glm::vec2 normalized{0.5f};  // 0..1 across the output, origin top-left
  bool dragging = false;       // left button held after a press inside the view
  glm::vec2 dragDelta{0.0f};   // normalised movement this frame while dragging
  float wheel = 0.0f;          // scroll steps this frame
};

struct FrameInput {
  double time = 0.0;           // simulation seconds, advanced in fixed steps
  float dt = 1.0f / 60.0f;     // the fixed step
  uint64_t frame = 0;          // frames since the scene was created
  uint32_t seed = 0;           // --seed: makes every stochastic choice reproducible
  bool reducedMotion = false;  // --reduced-motion: freeze what moves on its own, and grain
  double lastGpuMs = 0.0;      // the previous frame's GPU time, for adaptive quality
  CursorInput cursor;
  std::vector<int> keysPressed;  // GLFW key codes pressed this frame (gallery only)
};

// The HDR image a scene draws into: rgba16f, linear, in VK_IMAGE_LAYOUT_GENERAL, contents undefined
// at the start of the frame. Usable as storage image, colour attachment, sampled image and blit source.
struct RenderTarget {
  VkImage image = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkExtent2D extent{};
  VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
};

struct FrameContext {
  const gpu::Device& device;
  VkCommandBuffer cmd;
  gpu::PassTimer* timer;
  const RenderTarget& target;
  const FrameInput& input;
  uint32_t slot;  // frame-in-flight index, for per-frame resources

  // A labelled, timestamped GPU pass for the scope of the returned object.
  gpu::Pass pass(const char* name) const { return gpu::Pass(device, timer, cmd, name); }
};

struct SceneContext {
  const gpu::Device& device;
  gpu::ProgramLibrary& programs;
  uint32_t framesInFlight = 1;
};

class Scene {
 public:
  virtual ~Scene() = default;
  virtual void resize(VkExtent2D /*target*/) {}
  virtual void update(const FrameInput& input) = 0;  // once per fixed step
  virtual void record(const FrameContext& frame) = 0;
  virtual void drawPanel() {}  // Dear ImGui widgets, gallery only
  // "--set key=value" and the tests' way to change a parameter; false when the key is unknown or the
  // value malformed, with the reason in *error.
  virtual bool setParameter(std::string_view key, std::string_view value, std::string* error) = 0;
  virtual std::vector<std::string> parameterNames() const = 0;
  virtual float renderScale() const { return 1.0f; }  // fraction of the output the target covers
};

struct SceneInfo {
  std::string_view name;   // "kifs": used on the command line
  std::string_view title;  // "Volumetric KIFS": shown in the menu
  int key;                 // number key 1..9 in the gallery
  std::unique_ptr<Scene> (*create)(const SceneContext&);
};

std::span<const SceneInfo> sceneRegistry();
const SceneInfo* findScene(std::string_view name);

}  // namespace vitrine
