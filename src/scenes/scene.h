#pragma once
// A scene as the host drives it: its lifecycle, what it sees and how it is made. What it is by name
// (SceneInfo, the registry, the lookups) is scenes/catalogue.h, which needs no GPU. Scenes see the
// device, the program library, their declared images, the assets and the frame they are asked to draw
// (FrameInput and FrameContext, from frame/, which passes shared by scenes use without knowing of
// scenes); nothing else of the host.
#include "core/assets.h"
#include "frame/frame_context.h"
#include "frame/state_archive.h"
#include "params/schema.h"
#include "audio/audio_sink.h"
#include "scenes/catalogue.h"
#include "scenes/scene_events.h"

#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace vitrine::lights {
class Signals;
}

namespace vitrine {

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
  // The scene's parameters: its schema (SceneInfo::schema, scenes/catalogue.h) bound to its settings struct.
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
  // The light signals of the scene's own story (lights/signals.h names them: bloom's phase colour,
  // neon's tubes), from its CPU state after the last update; the frame's colours are the host's.
  virtual void lightSignals(lights::Signals& /*out*/) {}
};

// How a scene is made. Each scene's NAME_scene.h declares NAME::create; the factory table, generated
// with the registry from cmake/Scenes.cmake, pairs it with the scene's name. A piece found at run time
// (an ISF file) adds its own with addSceneFactory, as it adds its SceneInfo.
using SceneFactory = std::function<std::unique_ptr<Scene>(const SceneContext&)>;
struct SceneFactoryEntry {
  std::string_view name;
  std::unique_ptr<Scene> (*create)(const SceneContext&);
};
std::span<const SceneFactoryEntry> sceneFactories();

// The factory of a scene in the registry; empty for one it does not hold.
SceneFactory sceneFactory(const SceneInfo& info);
// The factory of a piece added to the registry at run time (addRuntimeScene).
void addSceneFactory(std::string name, SceneFactory create);

}  // namespace vitrine
