#pragma once
// What a scene is to the host: a name, a title, a number key, its parameter schema and a lifecycle.
// Scenes see the device, the program library, their declared images, the assets and the frame they
// are asked to draw (FrameInput and FrameContext, from frame/, which passes shared by scenes use
// without knowing of scenes); nothing else of the host.
#include "core/assets.h"
#include "frame/frame_context.h"
#include "frame/state_archive.h"
#include "params/schema.h"
#include "audio/audio_sink.h"
#include "scenes/scene_events.h"

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine {

// A scene's own verb that remote control (OSC, the web page) and input scripts can trigger, declared
// once with the scene: neon's "release x y z", glass's "shuffle". Arguments are numbers.
struct SceneAction {
  std::string_view name;
  std::span<const std::string_view> args;  // their names, in order; the count is the arity
  std::string_view help;
};

// The device, the program library and the scene's declared images (declare images there; the host owns
// and resizes them) come from GpuContext (frame/frame_context.h), which the scene's passes take.
struct SceneContext : GpuContext {
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
  // Checkpoints (record --checkpoint-every; frame/state_archive.h). A scene that can be checkpointed
  // walks everything later frames depend on that the parameters do not hold (the host keeps those)
  // through simulationState, saved after a frame or restored before the next update, so a film resumed
  // from it is frame for frame a whole run. One that cannot (its ranges simulate from frame 0) says no;
  // one that keeps nothing from one frame to the next says yes and walks nothing.
  virtual bool checkpoints() const { return false; }
  virtual void simulationState(StateArchive& /*state*/) {}
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

// Every scene, in menu order: generated from the list in cmake/Scenes.cmake.
std::span<const SceneInfo> sceneRegistry();
const SceneInfo* findScene(std::string_view name);
// What to say of a scene name no scene has (`where`: e.g. " in --set nope.grid=32"): the scenes there
// are, and the one meant when the name begins only that one ("nood": noodles).
std::string unknownScene(std::string_view name, std::string_view where = {});

}  // namespace vitrine
