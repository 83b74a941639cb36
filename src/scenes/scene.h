#pragma once
// What a scene is to the host: a name, a title, a number key, its parameter schema and a lifecycle.
// Scenes see the device, the program library, their declared images, the assets and the frame they
// are asked to draw; nothing else of the host.
#include "core/assets.h"
#include "gpu/frame_resources.h"
#include "gpu/pass_timer.h"
#include "gpu/program.h"
#include "gpu/rendering.h"
#include "gpu/stream.h"
#include "params/schema.h"
#include "audio/audio_sink.h"
#include "scenes/scene_events.h"

#include <glm/vec2.hpp>

#include <algorithm>
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
  bool present = false;        // over the view and not over the menu: the cursor is "there" (bloom's vapour)
};

// A scene's own verb that remote control (OSC, the web page) and input scripts can trigger, declared
// once with the scene: neon's "release x y z", glass's "shuffle". Arguments are numbers.
struct SceneAction {
  std::string_view name;
  std::span<const std::string_view> args;  // their names, in order; the count is the arity
  std::string_view help;
};

// One triggered action, checked against its declaration (name known, arity right, finite numbers).
struct ActionCall {
  std::string name;
  std::vector<float> args;
  bool operator==(const ActionCall&) const = default;
};

struct FrameInput {
  double time = 0.0;           // simulation seconds, advanced in fixed steps
  float dt = 1.0f / 60.0f;     // the fixed step
  uint64_t frame = 0;          // frames since the scene was created
  uint32_t seed = 0;           // --seed: makes every stochastic choice reproducible
  bool reducedMotion = false;  // --reduced-motion: freeze what moves on its own, and grain
  double lastGpuMs = 0.0;      // the previous frame's GPU time, for adaptive quality
  CursorInput cursor;
  std::vector<int> keysPressed;  // GLFW key codes pressed this frame (gallery and --input)
  std::vector<int> keysHeld;     // GLFW key codes down now (glass: Z held)
  std::vector<std::string> droppedFiles;  // paths dropped onto the window this frame (gallery only)
  std::vector<ActionCall> actions;        // the scene's own actions triggered this step, in order

  bool pressed(int key) const { return std::find(keysPressed.begin(), keysPressed.end(), key) != keysPressed.end(); }
  bool held(int key) const { return std::find(keysHeld.begin(), keysHeld.end(), key) != keysHeld.end(); }
};

struct FrameContext {
  const gpu::Device& device;
  VkCommandBuffer cmd;
  gpu::PassTimer* timer;
  // The HDR image the scene draws into: rgba16f, linear, contents undefined at the start of the
  // frame. Usable as storage image, colour attachment (or resolve target) and sampled image.
  gpu::Image& target;
  gpu::FrameResources& resources;  // the images the scene declared
  gpu::StreamArena& stream;        // per-frame CPU-written memory (uniform blocks, uploads)
  const FrameInput& input;
  uint32_t slot;  // frame-in-flight index, for per-frame resources

  // A labelled, timestamped GPU pass for the scope of the returned object.
  gpu::Pass pass(const char* name) const { return gpu::Pass(device, timer, cmd, name); }
  // The barrier from the resource's last use to `use` is derived; nothing else to write.
  void transition(gpu::Image& image, const gpu::ImageUse& use) const { image.use(cmd, use); }
  void transition(gpu::Buffer& buffer, const gpu::BufferUse& use) const { buffer.use(cmd, use); }
  gpu::Image& image(gpu::ImageHandle handle) const { return resources.current(handle); }
  // Colour/depth attachments transitioned, rendering begun, viewport and scissor set; ends with scope.
  gpu::Rendering rendering(const gpu::RenderingDesc& desc) const { return gpu::Rendering(cmd, desc); }
  // A uniform or parameter block for this frame.
  template <typename T> gpu::StreamSlice uniform(const T& value) const { return stream.writeValue(value); }
  void upload(gpu::Buffer& buffer, VkDeviceSize offset, std::span<const std::byte> data,
              const gpu::BufferUse& after) const {
    gpu::uploadBuffer(cmd, stream, buffer, offset, data, after);
  }
};

struct SceneContext {
  const gpu::Device& device;
  gpu::ProgramLibrary& programs;
  gpu::FrameResources& resources;  // declare images here; the host owns and resizes them
  const Assets& assets;            // fonts, panoramas, files named on the command line
  SceneEvents events;              // what happened, for tests and recordings (--events)
  audio::AudioSink& audio;         // the sound device, a WAV being rendered (--audio-out), or silence
  uint32_t framesInFlight = 1;
  // The gallery: real time, worker threads may run free. Headless, bench and tests: every step is
  // reproducible, so a scene's worker runs in lock-step with update().
  bool realtime = false;
};

class Scene {
 public:
  virtual ~Scene() = default;
  virtual void resize(VkExtent2D /*target*/) {}
  virtual void update(const FrameInput& input) = 0;  // once per fixed step
  virtual void record(const FrameContext& frame) = 0;
  virtual void drawPanel() {}  // extra Dear ImGui read-outs below the parameter panel, gallery only
  // The scene's parameters: its schema (SceneInfo::schema) bound to its settings struct.
  virtual params::Bound parameters() = 0;
  // Checks that span several parameters, run once on the final values of every change (noodles'
  // memory budget); a non-empty reason rejects the whole change.
  virtual std::string checkParameters() const { return {}; }
  virtual float renderScale() const { return 1.0f; }  // fraction of the output the target covers
  // The work a frame takes with `values` (this scene's settings struct), in any unit the scene likes:
  // the host compares a change's cost with the current one, and asks before a change that would make
  // the window freeze for seconds (noodles' strands, bloom's lattice). 1 for scenes whose cost hardly
  // depends on their parameters.
  virtual double frameCost(const void* /*values*/) const { return 1.0; }
  // Simulated seconds the scene's GPU simulation gave up since it was last asked: steps it was updated
  // for but could not run within one frame (bloom at a few frames a second). The gallery's clock
  // counts them as falling behind, so the overlay says so.
  virtual double takeGivenUpSeconds() { return 0.0; }
};

struct SceneInfo {
  std::string_view name;   // "kifs": used on the command line
  std::string_view title;  // "Volumetric KIFS": shown in the menu
  int key;                 // number key 1..9 in the gallery
  std::unique_ptr<Scene> (*create)(const SceneContext&);
  const params::Schema& (*schema)();  // the parameter declarations, no instance or GPU needed
  std::string_view input;  // for the help card: what the drag and the scene's own keys do
  std::span<const SceneAction> actions = {};  // what remote control and scripts may trigger

  const SceneAction* findAction(std::string_view actionName) const {
    for (const auto& action : actions)
      if (action.name == actionName) return &action;
    return nullptr;
  }
};

// A scene's SceneInfo: its factory makes a T from the context. constexpr, so every scene's info is
// constant-initialised and the registry never sees one before it exists.
template <typename T>
constexpr SceneInfo sceneInfo(std::string_view name, std::string_view title, int key,
                              const params::Schema& (*schema)(), std::string_view input,
                              std::span<const SceneAction> actions = {}) {
  return {name, title, key, [](const SceneContext& context) -> std::unique_ptr<Scene> {
            return std::make_unique<T>(context);
          },
          schema, input, actions};
}

// "" when `call` names one of the scene's actions with its arity and finite arguments; else why not.
std::string checkAction(const SceneInfo& info, const ActionCall& call);

std::span<const SceneInfo> sceneRegistry();
const SceneInfo* findScene(std::string_view name);

}  // namespace vitrine
