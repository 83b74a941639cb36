#pragma once
// A scene rendered with no window and no surface, one fixed step per frame: the headless CLI, the
// benchmark, recordings and the golden tests all drive this. Frame k shows time startTime + k x step (1/60
// unless a recording asks for another), computed
// in double from k (never by summing steps, which drifts), and an input script sees the same times.
#include "image/image.h"
#include "host/input_script.h"
#include "host/live_link.h"
#include "host/present/output.h"
#include "host/scene_renderer.h"

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace vitrine::host {

struct OffscreenConfig {
  std::string scene;
  VkExtent2D size{320, 180};
  double startTime = 0.0;
  uint32_t seed = 0;
  bool reducedMotion = false;
  // Applied in order after creation, before the parameters: presets by name (the scene's own, then the
  // user's: host/user_presets.h), then presetFiles.
  std::vector<std::string> presets;
  params::KeyValues parameters;      // applied together after the presets
  std::optional<InputScript> input;  // --input: the cursor and keys, as a person would use them
  EventSink* events = nullptr;       // --events: where the scene's events go
  audio::AudioSink* audio = nullptr; // --audio-out: where the scene's sound goes (null: silence)
  double step = 1.0 / 60.0;          // seconds between frames; a recording's 1 / (fps x samples a frame)
  LiveLink* live = nullptr;          // --map, --audio-in, --midi-in: mapped values and actions each step
  std::optional<maths::OutputWarp> warp;  // --output-warp: how the output shows the frame (a projector's)
  bool flashGuard = false;           // --flash-guard (on with --reduced-motion): frames shown through it
  std::vector<params::Preset> presetFiles;  // --preset-file: presets read from files, after the named ones
  std::filesystem::path shaderSources;      // what reloadShaders polls; empty: the source tree's shaders/
  std::vector<FilterSpec> filters;          // --filter: ISF filters after the scene, in order, with their values
};

struct FrameTimes {
  std::vector<gpu::PassTime> passes;
  double gpuMs = 0.0;  // sum of the passes: they run one after another on one queue
  double cpuMs = 0.0;  // update + recording + submission on the CPU
};

class Offscreen {
 public:
  Offscreen(const gpu::Device& device, const OffscreenConfig& config);

  // One frame after `steps` simulation steps, as the gallery draws after a slow frame (the steps'
  // frames are simulated, not drawn; frames() counts them all).
  // `seen` false: a frame nobody sees, simulated only where the scene can (FrameContext::draws); its
  // output is not defined.
  FrameTimes renderFrame(uint32_t steps = 1, bool seen = true);
  // The last frame's input drawn again with no simulation step, as the gallery draws while paused.
  FrameTimes redrawFrame();
  ImageRgba readback();  // the output of the last frame
  // Another output drawn after the main one each frame, through its own warp (a published node's, in a
  // benchmark); it must outlive this run's frames.
  void addOutput(Output& output) { others_.push_back(&output); }
  // The last frame's output on the GPU, for a pass submitted after renderFrame that reads it (a film's
  // frames packed into its encoder's bytes); the next renderFrame overwrites it.
  gpu::Image& output() { return output_; }
  uint64_t frames() const { return input_.frame; }
  // False when an input script still holds events past the last rendered frame.
  bool inputFinished() const { return !player_ || player_->finished(); }
  const SceneInfo& scene() const { return renderer_.info(); }
  params::Bound parameters() { return renderer_.parameters(); }
  SceneRenderer& renderer() { return renderer_; }
  double time() const { return startTime_ + double(input_.frame) * step_; }  // the next frame's
  VkExtent2D size() const { return size_; }
  std::string deviceName() const { return device_.properties().deviceName; }
  // Input from outside the script (a remote client), for the next frame: its actions, and a pointer
  // that drives the cursor instead of the script's while present.
  void addInput(std::vector<ActionCall> actions, std::optional<Pointer> pointer);

  // Checkpoints (host/offline/checkpoint.h). saveSimulation: between frames, every parameter's exact value and
  // the scene's own state (Scene::simulationState). restoreSimulation: before the first frame, puts the
  // run where it was `frames` frames in: the script and live input, which are cheap and keep their own
  // state, are replayed up to there without the scene, then the state is restored. Its values must be
  // `film`'s (the film's record.json), but for those a live mapping moves. Throws vitrine::Error saying
  // why the state does not fit (another build, another scene, other values).
  std::vector<std::byte> saveSimulation();
  void restoreSimulation(uint64_t frames, std::span<const std::byte> state, const params::KeyValues& film);
  const gpu::ProgramLibrary& programs() const { return programs_; }  // every pipeline the run made
  // Hot reload between frames, as the gallery does each frame: rebuilds the programs whose shaders
  // changed under OffscreenConfig::shaderSources; returns how many.
  int reloadShaders() { return programs_.reloadChanged(); }

 private:
  const gpu::Device& device_;
  Assets assets_ = Assets::locate();
  gpu::ProgramLibrary programs_;
  std::unique_ptr<FlashGuard> guard_;  // before the renderer: destroyed after it has drained the device
  SceneRenderer renderer_;
  VkExtent2D size_;
  gpu::Image output_;
  std::vector<Output*> others_;
  gpu::Unique<VkCommandPool> pool_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  FrameInput input_;
  double startTime_;
  double step_;
  std::optional<InputPlayer> player_;
  LiveLink* live_ = nullptr;
  EventSink* events_ = nullptr;
  std::vector<ActionCall> extraActions_;
  std::optional<Pointer> extraPointer_;
  std::optional<maths::OutputWarp> warp_;
  CursorTracker extraCursor_;
  bool rendered_ = false;
  void step();  // one simulation step: input_'s frame, its script input, the scene's update
  void gatherInput(EventSink* events);  // input_ for its frame: the script's, the remote's, live input's
  FrameTimes draw(std::chrono::steady_clock::time_point start);  // records, submits, waits: input_'s frame
};

}  // namespace vitrine::host
