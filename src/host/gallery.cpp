// The windowed gallery: the frame loop tying the window, swapchain, scene renderer, overlay and
// screenshots together. Two frames are in flight: the CPU records one while the GPU runs the other.
#include <GLFW/glfw3.h>
#include <glm/geometric.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <chrono>
#include <csignal>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <thread>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "gpu/check.h"
#include "core/assets.h"
#include "audio/engine.h"
#include "host/cursor_tracker.h"
#include "host/cost_guard.h"
#include "host/fixed_step.h"
#include "host/frame_slot.h"
#include "host/gallery_live.h"
#include "host/output_warp_file.h"
#include "host/output_window.h"
#include "host/projector_setup.h"
#include "core/atomic_file.h"
#include <nlohmann/json.hpp>
#include "host/gallery_settings.h"
#include "host/kiosk.h"
#include "host/live_capture.h"
#include "host/param_panel.h"
#include "host/playlist.h"
#include "host/user_presets.h"
#include "host/remote_link.h"
#include "host/menu.h"
#include "host/modes.h"
#include "host/overlay.h"
#include "host/scene_renderer.h"
#include "host/screenshot.h"
#include "host/swapchain.h"
#include "host/tier_watch.h"
#include "host/window.h"

namespace vitrine::host {
namespace {

using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t stopRequested = 0;

constexpr uint32_t kFramesInFlight = 2;
constexpr auto kShaderPollInterval = std::chrono::milliseconds(500);
constexpr auto kNoteSeconds = std::chrono::seconds(6);  // how long a screenshot's note stays
constexpr auto kToastSeconds = std::chrono::seconds(4);  // and how long it shows with the UI hidden
constexpr auto kReloadNoteSeconds = std::chrono::seconds(3);
const std::filesystem::path kExportFolder = "presets-exported";  // the panel's "export", beside screenshots/
// The scene renderer's present (compute) or blit (transfer) is the first use of an acquired image,
// so that is where the acquire is waited for.
constexpr VkPipelineStageFlags2 kAcquireStage =
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
constexpr gpu::ImageUse kAcquired{kAcquireStage, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};

const SceneInfo& namedScene(const std::string& name) {
  if (const SceneInfo* info = findScene(name)) return *info;
  throw Error(fmt::format("Unknown scene '{}'; vitrine --list-scenes shows them.", name));
}

const SceneInfo* sceneForKey(int key) {
  for (const auto& info : sceneRegistry())
    if (key == GLFW_KEY_0 + info.key) return &info;
  return nullptr;
}

// Each value checked by the scene's schema on a default settings struct, before the scene exists.
std::string checkValues(const SceneInfo& info, const params::KeyValues& values) {
  const auto scratch = info.schema().makeDefaults();
  return params::applyValues({&info.schema(), scratch.get()}, values);
}

// A --size the device cannot hold fails here, before a swapchain is made for it.
const gpu::Device& checkWindowSize(const gpu::Device& device, const std::optional<VkExtent2D>& size) {
  if (size) gpu::checkImageSize(device, *size);
  return device;
}

double secondsBetween(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

class Gallery {
 public:
  // `named`: the --scene the user asked for; null: the scene shown last time, else the first.
  // `playlist`: the kiosk's (--playlist), checked before the window opens; empty: every scene in turn.
  Gallery(const Options& options, const SceneInfo* named, std::vector<PlaylistEntry> playlist = {});
  const SceneInfo& showing() const { return renderer_->info(); }
  ~Gallery() { vkDeviceWaitIdle(device_); }  // also when leaving by an exception, with frames in flight
  Gallery(const Gallery&) = delete;
  Gallery& operator=(const Gallery&) = delete;
  int run();

 private:
  void frame();
  void handleKeys();
  void startSetup();
  void endSetup(ProjectorSetup::Key how);
  // Outputs by number: 0 the main window, then --outputs' windows in order.
  maths::OutputWarp& warpOf(size_t output);
  std::string_view outputName(size_t output) const { return output == 0 ? kMainOutput : outputs_[output - 1]->name(); }
  VkExtent2D outputExtent(size_t output) const { return output == 0 ? swapchain_.extent() : outputs_[output - 1]->extent(); }
  // How the main window shows the frame: its own warp, or the one of the output being set up.
  const maths::OutputWarp* shownWarp() { return setup_.active() && setupOutput_ > 0 ? &warpOf(setupOutput_) : warp(); }
  std::optional<maths::OutputWarp> savedWarp(std::string_view output);
  void keepWarp(size_t output);
  void switchScene(const SceneInfo& info);
  void simulate();
  void collect(uint32_t slot);
  void showMenu();
  void showToast();
  std::string clockNote() const;
  void recordWindowCopy(VkCommandBuffer cmd);
  void pollShaders();
  void applyEdit(const PanelEdit& edit);
  void rememberValues();
  void toggleCapture();
  double frameMs() const { return std::max(gpuMs_, frameSeconds_ * 1e3); }
  void applyEditNow(const PanelEdit& edit);
  bool managePresets(const PanelEdit& edit);
  std::string startScene(SceneRenderer& renderer, const SceneInfo& info);
  void kioskStep(double elapsed, bool touched);
  const SceneInfo& entryScene(size_t entry) const;
  size_t entryOf(const SceneInfo& info) const;
  void startEntryPreset(SceneRenderer& renderer, size_t entry);
  void finishFade();
  void applyRemote();
  void nowShowing();
  bool touchedThisFrame(const Pointer& pointer);

  Assets assets_ = Assets::locate();
  std::vector<std::string> missingAssets_ = assets_.missing();
  Window window_;
  std::optional<maths::OutputWarp> warp_;  // --output-warp: how this output shows the frame (a projector's)
  const maths::OutputWarp* warp() const { return warp_ ? &*warp_ : nullptr; }
  gpu::Instance instance_;
  Surface surface_;
  gpu::Device device_;
  gpu::ProgramLibrary programs_;
  GallerySettings settings_;
  params::PresetStore presets_ = openUserPresets(params::LoadMode::MoveBadAside);  // the user's, beside the settings
  MenuLayout menuLayout_;  // before the overlay, whose layout file is written when it goes
  TierWatch tiers_;        // before the renderers, whose scenes report to it
  audio::AudioOutput audio_;  // before the renderer: a scene going away may still send it a note
  FlashGuard guard_;          // before the renderers, which drain the device before it goes
  bool flashGuard_ = false;   // --flash-guard, --kiosk, --reduced-motion, then the menu's switch
  std::unique_ptr<SceneRenderer> renderer_;  // the scene showing
  std::unique_ptr<SceneRenderer> incoming_;  // kiosk mode: the scene fading in, made at the first fade
  Swapchain swapchain_;
  Overlay overlay_;
  Screenshots screenshots_;
  LiveCapture capture_;
  std::vector<FrameSlot> slots_;
  std::vector<std::unique_ptr<OutputWindow>> outputs_;  // --outputs: more windows showing the same frame
  uint64_t frameCount_ = 0;
  uint64_t sceneSerial_ = 0;           // counts scene switches and restarts
  std::vector<uint64_t> slotSerial_ = std::vector<uint64_t>(kFramesInFlight);  // the scene each slot drew

  FrameInput input_;  // the next simulation step's
  FrameInput shown_;  // the last step's: what the frame being recorded shows
  FixedStep steps_;   // after input_, whose dt it is built from
  StepCost stepCost_;  // what a step of the scene showing costs: how many fit in a frame
  TimeControl time_;  // pause, single steps, speed
  // The picture as the window shows it, at the window's size: what F12 and F9 save.
  std::optional<gpu::Image> windowCopy_;
  bool helpShown_ = false;
  ProjectorSetup setup_;                    // F7: the corner pin dragged on the picture
  const SceneInfo* beforeSetup_ = nullptr;  // the scene setup mode switched away from (to the card)
  size_t setupOutput_ = 0;                  // the output whose pin setup moves
  std::optional<size_t> setupShown_;        // the output whose setup the log last said is showing
  static constexpr std::string_view kMainOutput = "main";  // the main window's name in the settings file
  CursorTracker cursor_;
  std::vector<int> keys_;  // pressed since the last step
  std::vector<std::string> drops_;  // files dropped since the last step

  bool vsync_;
  std::string warpFile_;  // --output-warp's file, where projector setup writes a kept pin
  bool uiHidden_ = false;
  bool hasScene_ = false;
  const SceneInfo* nextScene_ = nullptr;
  Clock::time_point lastFrame_ = Clock::now();
  Clock::time_point firstShown_{};  // when the first frame was presented: the run's frame rate counts from it
  Clock::time_point lastShaderPoll_ = Clock::now();
  double frameSeconds_ = 0.0;  // smoothed over about twenty frames, for the fps readout
  double cpuMs_ = 0.0;
  double gpuMs_ = 0.0;  // the last finished frame's, all passes
  std::vector<gpu::PassTime> passes_;
  std::string reloadNote_;  // which shaders were reloaded, shown for kReloadNoteSeconds
  Clock::time_point reloadNoted_{};
  std::string note_;  // where the last screenshot went, a key with no scene: shown for kNoteSeconds
  Clock::time_point noted_{};
  ParamPanel panel_;
  std::string panelError_;  // why the last edit was refused
  std::optional<PanelEdit> costlyEdit_;  // an edit that would freeze the window, waiting for a yes
  std::string costlyWhy_;

  // Kiosk mode (--kiosk).
  std::optional<KioskSchedule> kiosk_;
  // --playlist: the kiosk's entries. Their presets apply over the saved values and are not remembered,
  // so that a line without a preset shows the scene as saved, whatever an earlier line set.
  std::vector<PlaylistEntry> playlist_;
  FrameInput incomingInput_, incomingShown_;  // the incoming scene's steps during a fade
  float fade_ = 0.0f;                         // its weight in the output
  Pointer lastPointer_;                       // to tell a moved mouse
  // Remote play (--remote): keys a client changed, per scene; kept out of the settings file unless
  // --remote-saves.
  std::optional<RemoteLink> remote_;
  std::map<std::string, std::set<std::string>, std::less<>> remoteKeys_;
  bool remoteSaves_ = false;
  std::vector<ActionCall> actions_;  // from clients, for the next step
  std::unique_ptr<GalleryLive> live_;  // audio, MIDI, gamepads and OSC through the mappings
};

Gallery::Gallery(const Options& options, const SceneInfo* named, std::vector<PlaylistEntry> playlist)
    : window_(options.size.value_or(VkExtent2D{1280, 720}), options.fullscreen, options.monitor, options.span),
      warp_(options.outputWarp.empty() ? std::nullopt : std::optional(readOutputWarp(options.outputWarp))),
      instance_({options.validation, window_.vulkanExtensions()}),
      surface_(window_.createSurface(instance_.handle())),
      device_(instance_, {options.device, surface_.handle()}),
      programs_(checkWindowSize(device_, options.size), VITRINE_SHADER_SOURCE_DIR, /*preferNewerSources=*/true),
      settings_(params::defaultSettingsPath(), options.resetSettings, /*keepScene=*/options.kiosk),
      guard_(device_, programs_),
      flashGuard_(flashGuardOn(options)),
      renderer_(std::make_unique<SceneRenderer>(device_, programs_, assets_, kFramesInFlight)),
      swapchain_(device_, surface_.handle(), window_.framebufferSize(), options.vsync),
      overlay_(device_, window_.handle(), swapchain_.format(), kFramesInFlight,
               {assets_.font("Fraunces"), assets_.font("CormorantSC")},
               // The menu's place, folds and sections, beside the settings file (not in a kiosk).
               options.kiosk || settings_.path().empty() ? std::filesystem::path()
                                                         : settings_.path().parent_path() / "gallery-menu.ini",
               options.resetSettings),
      screenshots_(device_, kFramesInFlight, "screenshots"),
      capture_(device_, kFramesInFlight, "captures"),
      steps_(input_.dt),
      vsync_(options.vsync),
      warpFile_(options.outputWarp),
      playlist_(std::move(playlist)) {
  overlay_.attach(swapchain_);
  keepInIni(menuLayout_);
  renderer_->setEventSink(&tiers_);
  renderer_->setAudioSink(&audio_);
  renderer_->setRealtime(true);
  remoteSaves_ = options.remoteSaves;
  if (options.remote) remote_.emplace(options.remoteBind, options.remoteAllow), remote_->setPresets(&presets_);
  if (options.kiosk) {
    uiHidden_ = true;
    window_.setCursorHidden(true);
  }
  for (uint32_t i = 0; i < kFramesInFlight; ++i) slots_.emplace_back(device_, i);
  if (!options.outputs.empty()) {
    std::vector<OutputPlacement> placements = readOutputs(options.outputs);
    for (size_t i = 0; i < placements.size(); ++i) {
      if (!placements[i].warp) placements[i].warp = savedWarp(placements[i].name);
      outputs_.push_back(std::make_unique<OutputWindow>(instance_, device_, placements[i], vsync_, kFramesInFlight, int(i) + 1));
    }
  }
  if (!warp_) warp_ = savedWarp(kMainOutput);  // a file named on the command line wins
  input_.seed = options.seed;
  input_.reducedMotion = options.reducedMotion;
  for (const auto& line : missingAssets_) std::fprintf(stderr, "vitrine: missing asset: %s\n", line.c_str());
  for (const auto& line : overlay_.fontProblems()) assets_.reportMissing(line);  // printed as reported
  for (const auto& line : settings_.warnings()) std::fprintf(stderr, "vitrine: settings: %s\n", line.c_str());
  for (const auto& line : presets_.warnings()) std::fprintf(stderr, "vitrine: presets: %s\n", line.c_str());
  // A preset file given to the gallery is imported: it joins the user's presets (listed as theirs, kept for
  // the next start) as well as applying to its scene below.
  for (const std::string& file : options.presetFiles)
    if (const std::string why = presets_.import(file); !why.empty())
      std::fprintf(stderr, "vitrine: presets: %s not imported: %s\n", file.c_str(), why.c_str());
  const SceneInfo* last = findScene(settings_.lastScene());
  const SceneInfo& firstScene = !playlist_.empty() ? namedScene(playlist_.front().scene)
                                : named          ? *named
                                : last           ? *last
                                                 : sceneRegistry().front();
  // --preset and --set apply over the saved values of the scenes they name, checked before a window
  // shows anything; like edits in the panel, they are remembered.
  for (const SceneInfo& info : sceneRegistry()) {
    const std::string_view first = firstScene.name;
    params::KeyValues values = settings_.valuesFor(info.name);
    bool given = false;  // the command line names values for this scene
    for (const params::Preset& preset : presetsForRun(options, info.name, info.name == first)) {
      values.insert(values.end(), preset.values.begin(), preset.values.end());
      given = true;
    }
    for (auto& kv : parametersFor(options, info.name, info.name == first)) values.push_back(std::move(kv)), given = true;
    if (!given) continue;
    if (auto why = checkValues(info, values); !why.empty())
      throw Error(fmt::format("Scene {} rejects {}", info.name, why));
    settings_.remember(info.name, std::move(values), Clock::now());
  }
  live_ = std::make_unique<GalleryLive>(options, settings_, audio_, firstScene.name);
  if (options.kiosk) {
    const auto scenes = sceneRegistry();
    // Cycling resumes after 30 s alone, or the dwell when shorter (but 10 s at least).
    if (playlist_.empty()) {
      kiosk_.emplace(scenes.size(), size_t(&firstScene - scenes.data()),
                     KioskTiming{options.dwell, 2.0, std::clamp(options.dwell, 10.0, 30.0)});
    } else {
      std::vector<double> dwells;
      for (const PlaylistEntry& entry : playlist_) dwells.push_back(entry.dwell);
      const double shortest = *std::min_element(dwells.begin(), dwells.end());
      kiosk_.emplace(std::move(dwells), 0, KioskTiming{shortest, 2.0, std::clamp(shortest, 10.0, 30.0)});
    }
    lastPointer_ = window_.takePointer();  // where the cursor rests is not a touch
  }
  switchScene(firstScene);
}

int Gallery::run() {
  while (!window_.shouldClose() && !stopRequested) {
    window_.pollEvents();
    if (window_.hidden()) {
      audio_.pause();  // minimised: no drone playing to nobody
      // Sleep on events (a few wake-ups a second, so a stop signal is still seen) until shown again.
      while (window_.hidden() && !window_.shouldClose() && !stopRequested) window_.waitForEvents(0.25);
      audio_.resume();
      lastFrame_ = Clock::now();  // time spent minimised is not simulated
      continue;
    }
    frame();
  }
  device_.waitIdle();
  // What the viewer saw: frames a second from the first one shown to the last (minimised time included).
  if (frameCount_ > 1) {
    const double seconds = secondsBetween(firstShown_, Clock::now());
    std::fprintf(stderr, "vitrine: showed %llu frames in %.1f s (%.1f fps)\n", (unsigned long long)(frameCount_ - 1),
                 seconds, double(frameCount_ - 1) / std::max(seconds, 1e-9));
  }
  for (uint32_t slot = 0; slot < kFramesInFlight; ++slot)
    if (auto note = screenshots_.collect(slot)) std::printf("vitrine: %s\n", note->c_str());
  if (auto finished = capture_.takeFinished()) std::printf("vitrine: %s\n", finished->c_str());
  if (instance_.validationMessages() > 0) {
    std::fprintf(stderr, "%d validation messages: failing.\n", instance_.validationMessages());
    return 3;
  }
  return 0;
}

// The gallery keys an installation's visitors may use: the scene keys (and the scenes' own keys).
// Esc stays for whoever runs it; everything that would change the installation is ignored.
bool kioskAllows(int key) { return key == GLFW_KEY_ESCAPE || sceneForKey(key) != nullptr; }

// After the menu has seen this frame's clicks and keys: a field that a click activated in this very
// frame (at 1 fps, a click and the digits typed after it arrive together) already has the keyboard.
void Gallery::handleKeys() {
  const std::vector<int> keys = window_.takeKeys();
  if (overlay_.wantsKeyboard()) return;  // typed into a field, not commands
  const auto& held = window_.keysHeld();
  const bool shift = std::find(held.begin(), held.end(), GLFW_KEY_LEFT_SHIFT) != held.end() ||
                     std::find(held.begin(), held.end(), GLFW_KEY_RIGHT_SHIFT) != held.end();
  for (int key : keys) {
    if (kiosk_ && !kioskAllows(key)) continue;
    if (setup_.active()) {  // its keys are setup's: Esc undoes the pin rather than closing the gallery
      const ProjectorSetup::Key used = setup_.key(key, shift, outputExtent(setupOutput_), warpOf(setupOutput_));
      if (used != ProjectorSetup::Key::Ignored) {
        if (used != ProjectorSetup::Key::Used) endSetup(used);
        continue;
      }
    }
    switch (key) {
      case GLFW_KEY_ESCAPE:
        window_.close();
        break;
      case GLFW_KEY_TAB:
        uiHidden_ = !uiHidden_;
        break;
      case GLFW_KEY_M:
        audio_.setMuted(!audio_.muted());
        break;
      case GLFW_KEY_V:
        vsync_ = !vsync_;
        break;
      case GLFW_KEY_F11:
        window_.toggleFullscreen();
        break;
      case GLFW_KEY_F12:
        screenshots_.request();
        break;
      case GLFW_KEY_F9:
        toggleCapture();
        break;
      case GLFW_KEY_P:
        time_.paused = !time_.paused;
        break;
      case GLFW_KEY_F1:
      case GLFW_KEY_SLASH:  // '?' on most layouts
        helpShown_ = !helpShown_;
        if (helpShown_) uiHidden_ = false;  // the card is part of the UI
        break;
      case GLFW_KEY_PERIOD:
        if (time_.paused) time_.stepRequested = true;
        break;
      case GLFW_KEY_LEFT_BRACKET:
        time_.slower();
        break;
      case GLFW_KEY_RIGHT_BRACKET:
        time_.faster();
        break;
      case GLFW_KEY_BACKSLASH:
        time_.normal();
        break;
      case GLFW_KEY_F7:
        startSetup();
        break;
      case GLFW_KEY_F5:  // the scene from its first frame, its parameters kept
        nextScene_ = &renderer_->info();
        break;
      default:
        if (const SceneInfo* info = sceneForKey(key)) {
          nextScene_ = info;
        } else if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) {  // the footer's range says which exist
          note_ = fmt::format("no scene on key {}: the scenes are on {}", key - GLFW_KEY_0, sceneKeyRange());
          noted_ = Clock::now();
        }
    }
  }
  keys_.insert(keys_.end(), keys.begin(), keys.end());
  for (std::string& path : window_.takeDrops()) drops_.push_back(std::move(path));
}

// Creates `info` in `renderer` with its remembered values, and any a client sent while it was away.
// Returns why it could not start; only kiosk mode survives that (elsewhere the error ends the run).
std::string Gallery::startScene(SceneRenderer& renderer, const SceneInfo& info) {
  try {
    renderer.setScene(info);
  } catch (const Error& e) {
    if (!kiosk_) throw;
    renderer.clear();
    return e.what();
  }
  tiers_.started(info.name);
  // Saved values that do not fit together on this device (each one was valid on its own): the ones
  // that conflict are dropped, the rest kept.
  const params::FittedValues fitted = params::applyWhatFits(
      settings_.valuesFor(info.name), [&](const params::KeyValues& values) { return renderer.applyParameters(values); });
  if (!fitted.dropped.empty())
    std::fprintf(stderr, "vitrine: settings for %.*s: dropped %s (%s); the other saved values are kept\n",
                 int(info.name.size()), info.name.data(), fmt::format("{}", fmt::join(fitted.dropped, ", ")).c_str(),
                 fitted.why.c_str());
  if (remote_)  // values a client sent while it was away, through the same guard as the live ones
    for (const auto& [key, value] : remote_->applyWaiting(renderer, frameMs()))
      remoteKeys_[std::string(info.name)].insert(key);
  return {};
}

size_t registryIndex(const SceneInfo& info) { return size_t(&info - sceneRegistry().data()); }

void Gallery::switchScene(const SceneInfo& info) {
  if (hasScene_ && playlist_.empty()) rememberValues();  // switching back restores them
  if (incoming_) incoming_->clear();  // a number key during a fade: that scene, no fade
  fade_ = 0.0f;
  const SceneInfo* chosen = &info;
  // The old scene is retired behind the frames still using it. In kiosk mode a scene that cannot
  // start is skipped for the next one; when none starts, the kiosk starts over (runGallery).
  for (std::string failed; !(failed = startScene(*renderer_, *chosen)).empty();) {
    std::fprintf(stderr, "vitrine: kiosk: skipping %.*s: %s\n", int(chosen->name.size()), chosen->name.data(),
                 failed.c_str());
    for (size_t entry = 0; entry < (playlist_.empty() ? sceneRegistry().size() : playlist_.size()); ++entry)
      if (&entryScene(entry) == chosen) kiosk_->failed(entry);
    const SceneInfo& next = entryScene(kiosk_->current());
    if (&next == chosen) throw Error("kiosk: no scene starts on this device");
    chosen = &next;
  }
  if (kiosk_) {
    // A playlist shows the entry showing, if it is this scene's, else the scene's first entry.
    const size_t entry = &entryScene(kiosk_->current()) == chosen ? kiosk_->current() : entryOf(*chosen);
    kiosk_->jumpTo(entry);
    startEntryPreset(*renderer_, entry);
  }
  missingAssets_ = assets_.missing();  // with what the scene could not find
  hasScene_ = true;
  ++sceneSerial_;
  passes_.clear();  // the old scene's timings are not this one's
  costlyEdit_.reset();
  panel_.forget();
  panelError_.clear();
  if (!kiosk_) settings_.showing(chosen->name, Clock::now());  // the kiosk's cycle is not the gallery's choice
  input_.frame = 0;
  input_.time = 0.0;
  steps_.restart();
  stepCost_ = {};
  window_.setTitle(fmt::format("Vitrine — {}", chosen->title));
  nowShowing();
}

// The scene showing changed (a switch, a finished fade): its mappings, and every page told.
void Gallery::nowShowing() {
  live_->showing(renderer_->info());
  if (!remote_) return;
  remote_->setMappings(live_->mappingLines());
  remote_->publish(*renderer_, true);
}

// The scene of a kiosk entry: a playlist's line, else the registry's scene of that index.
const SceneInfo& Gallery::entryScene(size_t entry) const {
  return playlist_.empty() ? sceneRegistry()[entry] : namedScene(playlist_[entry].scene);
}

// The kiosk entry that shows `info`: its first line in a playlist (the line showing when none does).
size_t Gallery::entryOf(const SceneInfo& info) const {
  if (playlist_.empty()) return registryIndex(info);
  for (size_t entry = 0; entry < playlist_.size(); ++entry)
    if (playlist_[entry].scene == info.name) return entry;
  return kiosk_->current();
}

// A playlist line's preset over the scene's saved values, just after it started; a preset the scene
// refuses on this device (each value was checked when the playlist was read) is said and skipped.
void Gallery::startEntryPreset(SceneRenderer& renderer, size_t entry) {
  if (playlist_.empty() || playlist_[entry].preset.empty() || playlist_[entry].scene != renderer.info().name) return;
  const PlaylistEntry& line = playlist_[entry];
  FoundPreset found = findPreset(line.scene, line.preset, &presets_);
  std::string why = found.preset ? renderer.applyParameters(found.preset->values) : found.why;
  if (!why.empty())
    std::fprintf(stderr, "vitrine: kiosk: %s without preset '%s': %s\n", line.scene.c_str(), line.preset.c_str(),
                 why.c_str());
}

// Kiosk mode, once a frame: a fade begins (the incoming scene starts in the second renderer), goes
// on, or ends (the renderers swap places).
void Gallery::kioskStep(double elapsed, bool touched) {
  const KioskSchedule::Plan plan = kiosk_->advance(elapsed, touched);
  if (plan.begin) {
    const SceneInfo& info = entryScene(*plan.begin);
    if (!incoming_) {
      incoming_ = std::make_unique<SceneRenderer>(device_, programs_, assets_, kFramesInFlight);
      incoming_->setAudioSink(&audio_);
      incoming_->setEventSink(&tiers_);
      incoming_->setRealtime(true);
    }
    if (auto failed = startScene(*incoming_, info); !failed.empty()) {
      std::fprintf(stderr, "vitrine: kiosk: skipping %.*s: %s\n", int(info.name.size()), info.name.data(),
                   failed.c_str());
      kiosk_->failed(*plan.begin);
      fade_ = 0.0f;
      return;
    }
    startEntryPreset(*incoming_, *plan.begin);
    incomingInput_ = FrameInput{};
    incomingInput_.seed = input_.seed;
    incomingInput_.reducedMotion = input_.reducedMotion;
    incomingShown_ = incomingInput_;
  }
  if (plan.finish) finishFade();
  fade_ = plan.fade.value_or(0.0f);
}

void Gallery::finishFade() {
  if (!incoming_ || !incoming_->hasScene()) return;
  if (playlist_.empty()) rememberValues();
  std::swap(renderer_, incoming_);
  incoming_->clear();  // the scene that faded out
  input_ = incomingInput_;
  shown_ = incomingShown_;
  ++sceneSerial_;
  passes_.clear();
  panel_.forget();
  panelError_.clear();
  missingAssets_ = assets_.missing();
  window_.setTitle(fmt::format("Vitrine — {}", renderer_->info().title));
  nowShowing();
}

void Gallery::frame() {
  if (nextScene_) switchScene(*std::exchange(nextScene_, nullptr));
  if (const VkExtent2D size = window_.framebufferSize(); !swapchain_.fits(size, vsync_)) {
    swapchain_.recreate(size, vsync_);
    overlay_.attach(swapchain_);
  }
  const uint32_t slot = uint32_t(frameCount_ % kFramesInFlight);
  FrameSlot& current = slots_[slot];
  current.wait();
  collect(slot);
  const auto image = swapchain_.acquire(current.imageAcquired());
  if (!image) return;  // out of date: rebuilt at the start of the next frame

  const auto start = Clock::now();
  settings_.tick(start);
  overlay_.beginFrame();  // first: its view of this frame's clicks decides which belong to the scene
  simulate();
  showMenu();
  showToast();
  if (setup_.active()) setup_.draw(warpOf(setupOutput_), swapchain_.extent(), outputName(setupOutput_), outputs_.size() + 1);
  handleKeys();
  VkCommandBuffer cmd = current.begin();
  const bool compute = swapchain_.computeWrites();
  Crossfade fade;
  if (incoming_ && incoming_->hasScene()) {  // kiosk mode's cross-fade: both scenes run and draw
    incoming_->recordTarget(cmd, slot, incomingShown_, frameExtent(swapchain_.extent(), shownWarp()));
    fade = {&incoming_->target(), fade_};
  }
  renderer_->setFlashGuard(flashGuard_ ? &guard_ : nullptr);
  renderer_->record(cmd, slot, shown_,
                    BlitDestination{swapchain_.image(*image), swapchain_.extent(), kAcquired, gpu::use::ColorAttachment,
                                    compute ? swapchain_.view(*image) : VK_NULL_HANDLE, compute, shownWarp()},
                    fade);
  if (screenshots_.requested() || capture_.active()) {
    recordWindowCopy(cmd);
    const VkExtent2D rendered = renderer_->target().extent2d();
    screenshots_.record(cmd, slot, *windowCopy_, rendered, renderer_->info().name, &renderer_->timer());
    capture_.record(cmd, slot, *windowCopy_, rendered, &renderer_->timer());
  }
  // The other outputs show the same frame, each through its own warp; one that is hidden or being
  // rebuilt misses this frame.
  std::vector<std::pair<VkSemaphore, VkSemaphore>> outputsDrawn;
  for (auto& output : outputs_)
    if (output->acquire(slot, vsync_)) {
      renderer_->recordOutput(cmd, output->destination(kAcquireStage), fade);
      outputsDrawn.emplace_back(output->acquired(slot), output->renderFinished());
    }
  slotSerial_[slot] = sceneSerial_;
  overlay_.record(cmd, *image, &renderer_->timer());
  current.submit(kAcquireStage, swapchain_.renderFinished(*image), outputsDrawn);
  cpuMs_ = secondsBetween(start, Clock::now()) * 1e3;
  swapchain_.present(*image);
  for (auto& output : outputs_) output->present();
  // One line once the window shows its first frame: what is showing where (and what the gallery's
  // checks wait for instead of guessing how long a start takes).
  if (frameCount_++ == 0) {
    firstShown_ = Clock::now();
    std::fprintf(stderr, "vitrine: showing %s on %s\n", std::string(renderer_->info().name).c_str(),
                 device_.properties().deviceName);
  }
  // And one when projector setup first shows for an output, its card built: the calibration card
  // can take seconds to build on a busy CPU, and a corner dragged before then would be lost.
  if (!setup_.active()) setupShown_.reset();
  else if (setupShown_ != setupOutput_ && !nextScene_) {
    setupShown_ = setupOutput_;
    std::fprintf(stderr, "vitrine: projector setup of %s\n", std::string(outputName(setupOutput_)).c_str());
  }
  pollShaders();
}

// What the GPU has finished for this slot: its pass timings, and a screenshot taken in it.
void Gallery::collect(uint32_t slot) {
  // A slot last drawn by the scene before a switch or restart has that scene's timings: skipped.
  if (slotSerial_[slot] == sceneSerial_) passes_ = renderer_->timer().collect(slot);
  gpuMs_ = 0.0;
  for (const auto& pass : passes_) gpuMs_ += pass.ms;
  input_.lastGpuMs = gpuMs_;
  capture_.collect(slot);
  if (auto finished = capture_.takeFinished()) std::printf("vitrine: %s\n", finished->c_str());
  if (auto note = screenshots_.collect(slot)) {
    std::printf("vitrine: %s\n", note->c_str());
    std::fflush(stdout);  // said now, also when the console is a log file
    note_ = std::move(*note);
    noted_ = Clock::now();
  }
  if (!note_.empty() && Clock::now() - noted_ > kNoteSeconds) note_.clear();
}

void Gallery::simulate() {
  const auto now = Clock::now();
  const double elapsed = secondsBetween(lastFrame_, now);
  lastFrame_ = now;
  frameSeconds_ += (elapsed - frameSeconds_) * 0.05;
  Pointer pointer = window_.takePointer();
  bool touched = touchedThisFrame(pointer);
  if (remote_) {
    const RemoteApplied applied = remote_->apply(*renderer_, nullptr, input_.time, frameMs());
    touched = touched || applied.touched;
    if (applied.scene) nextScene_ = applied.scene;  // from the next frame, like a number key
    for (const auto& [key, value] : applied.values) remoteKeys_[std::string(renderer_->info().name)].insert(key);
    actions_.insert(actions_.end(), applied.actions.begin(), applied.actions.end());
    for (const auto& [source, value] : applied.sources) live_->link().sources().set(source, value);
    if (auto phone = remote_->pointer(window_.framebufferSize())) pointer = *phone;  // a phone drives the cursor
    remote_->publish(*renderer_);
  }
  if (kiosk_) kioskStep(elapsed, touched);
  if (setup_.active()) setup_.pointer(pointer, warpOf(setupOutput_));
  cursor_.observe(pointer, setup_.active() || (!uiHidden_ && overlay_.wantsMouse()));  // setup's mouse is not the scene's
  // Every step that is due, unless a step costs more than the time it stands for (StepCost).
  const int due = time_.due(steps_, elapsed, stepCost_.affordable(elapsed), renderer_->scene().takeGivenUpSeconds());
  const bool firstSteps = input_.frame == 0;  // a scene's first update builds things: not its cost
  const auto simulating = Clock::now();
  for (int left = due; left > 0; --left) {
    input_.cursor = cursor_.take();
    input_.keysPressed = std::exchange(keys_, {});
    input_.keysHeld = overlay_.wantsText() ? std::vector<int>{} : window_.keysHeld();
    input_.droppedFiles = std::exchange(drops_, {});
    input_.actions = std::exchange(actions_, {});
    live_->step(*renderer_, input_);
    renderer_->scene().update(input_);
    // A frame's GPU time is news to its first step only: the automatic tiers count frames, and a
    // slow frame followed by many steps must not count as many slow frames.
    input_.lastGpuMs = 0.0;
    shown_ = input_;
    input_.time += input_.dt;
    ++input_.frame;
    if (incoming_ && incoming_->hasScene()) {  // the scene fading in runs on its own clock, untouched
      incoming_->scene().update(incomingInput_);
      incomingShown_ = incomingInput_;
      incomingInput_.time += incomingInput_.dt;
      ++incomingInput_.frame;
    }
  }
  if (!firstSteps) stepCost_.measured(due, secondsBetween(simulating, Clock::now()));
}

// Kiosk mode: did a person do anything? A key, a click, a scroll, a drop, or a mouse that moved.
bool Gallery::touchedThisFrame(const Pointer& pointer) {
  const bool moved = pointer.inside && glm::length(pointer.pixels - lastPointer_.pixels) > 2.0f;
  lastPointer_ = pointer;
  return moved || pointer.leftPressed || pointer.leftHeld || pointer.wheel != 0.0f || !keys_.empty() ||
         !drops_.empty();
}

void Gallery::showMenu() {
  if (uiHidden_) return;
  const double fps = frameSeconds_ > 0.0 ? 1.0 / frameSeconds_ : 0.0;
  MenuState state{renderer_->info(), renderer_->scene(), fps, cpuMs_, passes_, vsync_, programs_.error(),
                  note_, missingAssets_, overlay_.titleFont(), &panel_, panelError_, time_,
                  helpShown_, capture_.status(renderer_->info().name), capture_.active(), reloadNote_,
                  remote_ ? remote_->status() : std::string(), costlyEdit_ ? costlyWhy_ : std::string(),
                  tiers_.describe(renderer_->info().name, params::snapshot(renderer_->parameters())),
                  clockNote(), &menuLayout_};
  state.userPresets = presets_.presetsOf(renderer_->info().name);
  state.livePanel = &live_->panel();
  state.live = live_->panelState();
  state.flashGuard = flashGuard_;
  const MenuChoice choice = drawMenu(state);
  if (live_->apply(choice.live, panel_) && remote_) remote_->setMappings(live_->mappingLines());
  vsync_ = choice.vsync;
  if (choice.flashGuard && !flashGuard_) guard_.reset();  // what it held is stale: count from the next frame
  flashGuard_ = choice.flashGuard;
  time_ = choice.time;
  time_.speed = TimeControl::clampSpeed(time_.speed);
  helpShown_ = choice.help;
  if (choice.scene) nextScene_ = choice.scene;
  if (choice.edit) applyEdit(*choice.edit);
  if (choice.capture != capture_.active()) toggleCapture();
  if (choice.costly && costlyEdit_) {
    if (*choice.costly) applyEditNow(*costlyEdit_);
    costlyEdit_.reset();
  }
}

// With the UI hidden (Tab), where a screenshot went and a clock that falls behind still show, briefly
// and small, in a corner. A kiosk shows nothing.
// Projector setup shows the calibration card, when this build has one, and the UI it needs.
void Gallery::startSetup() {
  if (setup_.active()) return;
  setupOutput_ = 0;
  setup_.start(warpOf(0));
  if (const SceneInfo* card = findScene("calibrate"); card && card != &renderer_->info())
    beforeSetup_ = &renderer_->info(), nextScene_ = card;
  note_ = "projector setup";
  noted_ = Clock::now();
}

void Gallery::endSetup(ProjectorSetup::Key how) {
  if (how != ProjectorSetup::Key::Undone) keepWarp(setupOutput_);
  else note_ = fmt::format("projector setup of {} undone", outputName(setupOutput_)), noted_ = Clock::now();
  if (how == ProjectorSetup::Key::Next) {  // F7 again: the next output's pin, the card still showing
    setupOutput_ = (setupOutput_ + 1) % (outputs_.size() + 1);
    setup_.start(warpOf(setupOutput_));
    return;
  }
  if (beforeSetup_) nextScene_ = std::exchange(beforeSetup_, nullptr);
}

maths::OutputWarp& Gallery::warpOf(size_t output) {
  if (output > 0) return outputs_[output - 1]->warp();
  if (!warp_) warp_.emplace();
  return *warp_;
}

// An output's warp as the settings file keeps it (projector setup's last kept pin); one the file holds
// but this build refuses is a warning, and the output shows the whole frame.
std::optional<maths::OutputWarp> Gallery::savedWarp(std::string_view output) {
  const nlohmann::ordered_json* saved = settings_.warpFor(output);
  if (!saved) return std::nullopt;
  try {
    return outputWarpFromJson(nlohmann::json::parse(saved->dump()),
                              fmt::format("{}: outputs.{}", settings_.path().string(), output));
  } catch (const Error& e) {
    std::fprintf(stderr, "vitrine: settings: %s; showing the whole frame there\n", e.what());
    return std::nullopt;
  }
}

// A kept pin goes to the settings file under the output's name, and for the main window also to
// --output-warp's file when one was given (which wins over the settings at the next start).
void Gallery::keepWarp(size_t output) {
  const maths::OutputWarp& warp = warpOf(output);
  settings_.setWarp(outputName(output), warp.isIdentity() ? nlohmann::ordered_json() : nlohmann::ordered_json(outputWarpToJson(warp)),
                    Clock::now());
  note_ = fmt::format("projector setup of {} kept in the settings", outputName(output));
  if (output == 0 && !warpFile_.empty()) {
    const std::string text = outputWarpToJson(warp).dump(2) + "\n";
    writeFileAtomically(warpFile_, std::span(reinterpret_cast<const unsigned char*>(text.data()), text.size()));
    note_ = fmt::format("projector setup of {} kept in {} and the settings", outputName(output), warpFile_);
  }
  noted_ = Clock::now();
}

void Gallery::showToast() {
  if (!uiHidden_ || kiosk_) return;
  std::string text;
  if (!note_.empty() && Clock::now() - noted_ < kToastSeconds) text = note_;
  if (const std::string clock = clockNote(); !clock.empty()) text += (text.empty() ? "" : "\n") + clock;
  if (text.empty()) return;
  drawToast(text);
}

// Said while the simulation cannot keep up with the wall clock, and for a few seconds after.
std::string Gallery::clockNote() const {
  if (!steps_.behind() || time_.paused) return {};
  return fmt::format("simulation behind the clock: {:.0f}% of real time ({:.1f} ms a step of {:.1f} ms)",
                     steps_.kept() * 100.0, stepCost_.perStep() * 1e3, steps_.step() * 1e3);
}

// The scene scaled to the window, as the present pass draws it, into an HDR image of the window's size.
void Gallery::recordWindowCopy(VkCommandBuffer cmd) {
  const VkExtent2D size = swapchain_.extent();
  if (!windowCopy_ || windowCopy_->extent2d().width != size.width || windowCopy_->extent2d().height != size.height) {
    if (windowCopy_) device_.retire(std::move(*windowCopy_));  // a frame in flight may still read it
    gpu::ImageDesc desc;
    desc.extent = {size.width, size.height, 1};
    desc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    desc.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    windowCopy_.emplace(device_, desc, "window copy");
  }
  renderer_->recordScaled(cmd, *windowCopy_);
}

void Gallery::toggleCapture() {
  std::printf("vitrine: %s\n", capture_.toggle(renderer_->info().name).c_str());
  std::fflush(stdout);
}

// Every panel edit goes through the same validation as --set; a refused one leaves every value as it
// was. One that would freeze the window for seconds is asked about first.
void Gallery::applyEdit(const PanelEdit& edit) {
  if (managePresets(edit)) return;
  params::KeyValues change = edit.values;
  if (edit.what == PanelEdit::What::Preset)
    if (FoundPreset found = findPreset(renderer_->info().name, edit.preset, &presets_); found.preset)
      change = found.preset->values;
  if (edit.what != PanelEdit::What::ResetAll)
    if (std::string why = freezeWarning(renderer_->costRatio(change), frameMs()); !why.empty()) {
      costlyEdit_ = edit;
      costlyWhy_ = std::move(why);
      return;
    }
  applyEditNow(edit);
}

void Gallery::applyEditNow(const PanelEdit& edit) {
  auto& remoteKeys = remoteKeys_[std::string(renderer_->info().name)];  // what the user sets here is theirs
  if (edit.what == PanelEdit::What::Values)
    for (const auto& kv : edit.values) remoteKeys.erase(kv.first);
  else
    remoteKeys.clear();
  switch (edit.what) {
    case PanelEdit::What::Values: panelError_ = renderer_->applyParameters(edit.values); break;
    case PanelEdit::What::Preset: {
      FoundPreset found = findPreset(renderer_->info().name, edit.preset, &presets_);
      panelError_ = found.preset ? renderer_->applyParameters(found.preset->values) : found.why;
      break;
    }
    case PanelEdit::What::ResetAll:
      params::resetToDefaults(renderer_->parameters());
      panelError_.clear();
      break;
    default: break;  // the user's presets: managePresets
  }
  rememberValues();
  if (remote_) remote_->publish(*renderer_, true);
}

// Saving, renaming, deleting or exporting one of the user's presets of the scene showing (true), said in
// the note or, when refused, where the panel shows refusals. The values themselves do not change.
bool Gallery::managePresets(const PanelEdit& edit) {
  const std::string scene(renderer_->info().name);
  std::string why, done;
  switch (edit.what) {
    case PanelEdit::What::SavePreset:
      why = presets_.save({scene, edit.preset, params::snapshot(renderer_->parameters(), /*includeTransient=*/false)});
      done = fmt::format("saved preset '{}'", edit.preset);
      break;
    case PanelEdit::What::RenamePreset:
      why = presets_.rename(scene, edit.preset, edit.newName);
      done = fmt::format("renamed preset '{}' to '{}'", edit.preset, edit.newName);
      break;
    case PanelEdit::What::DeletePreset:
      why = presets_.remove(scene, edit.preset);
      done = fmt::format("deleted preset '{}'", edit.preset);
      break;
    case PanelEdit::What::ExportPreset: {
      // Into the working folder, as screenshots are: a file to hand on, read back by --preset-file.
      const std::filesystem::path file = kExportFolder / presets_.fileOf(scene, edit.preset).filename();
      why = presets_.exportTo(scene, edit.preset, file);
      done = fmt::format("wrote preset '{}' to {}", edit.preset, std::filesystem::absolute(file).string());
      break;
    }
    default: return false;
  }
  panelError_ = why;
  if (why.empty()) {
    note_ = done;
    noted_ = Clock::now();
    std::printf("vitrine: %s\n", done.c_str());
    std::fflush(stdout);
    if (remote_) remote_->publish(*renderer_, true);
  }
  return true;
}

// What a client changed is kept out of the settings file (unless --remote-saves): those keys keep
// the values saved before.
void Gallery::rememberValues() {
  const std::string_view scene = renderer_->info().name;
  params::KeyValues values = params::snapshot(renderer_->parameters());
  std::set<std::string> theirs;  // keys whose live value is not the user's to save
  if (const auto remote = remoteKeys_.find(scene); remote != remoteKeys_.end() && !remoteSaves_)
    theirs = remote->second;
  if (live_)  // a mapping plays these: the values the user saved stay
    for (std::string& key : live_->drivenKeys()) theirs.insert(std::move(key));
  if (!theirs.empty()) {
    std::erase_if(values, [&](const auto& kv) { return theirs.contains(kv.first); });
    for (auto& kv : settings_.valuesFor(scene))
      if (theirs.contains(kv.first)) values.push_back(std::move(kv));
  }
  settings_.remember(scene, std::move(values), Clock::now());
}

// Shader sources are polled a couple of times a second: often enough to feel live, rarely enough
// that the file-system checks cost nothing.
void Gallery::pollShaders() {
  const auto now = Clock::now();
  if (now - lastShaderPoll_ < kShaderPollInterval) return;
  lastShaderPoll_ = now;
  programs_.reloadChanged();
  // Reloads, and edited sources a newly opened scene compiled: said once, briefly, here and on the console.
  if (const auto names = programs_.takeReloaded(); !names.empty()) {
    reloadNote_ = fmt::format("reloaded {}", fmt::join(names, ", "));
    reloadNoted_ = now;
    std::printf("vitrine: %s\n", reloadNote_.c_str());
  }
  if (!reloadNote_.empty() && now - reloadNoted_ > kReloadNoteSeconds) reloadNote_.clear();
}

}  // namespace

int runGallery(const Options& options) {
  const SceneInfo* named = options.scene.empty() ? nullptr : &namedScene(options.scene);  // a typo fails first
  // SIGTERM (a kiosk's service manager) and Ctrl-C end the loop like Esc: settings are flushed, the
  // device is idled and destroyed in order. The handler only sets a flag.
  std::signal(SIGTERM, [](int) { stopRequested = 1; });
  std::signal(SIGINT, [](int) { stopRequested = 1; });
  if (!options.kiosk) return Gallery(options, named).run();
  // A bad playlist is refused here, naming its line, before a window opens.
  std::vector<PlaylistEntry> playlist;
  if (!options.playlist.empty()) {
    params::PresetStore presets = openUserPresets();
    playlist = loadPlaylist(options.playlist,
                            {[](std::string_view scene) { return findScene(scene) != nullptr; },
                             [&](std::string_view scene, std::string_view name) {
                               return findPreset(scene, name, &presets).why;
                             }});
  }

  // The kiosk never stops: whatever ends a gallery once it has shown a frame (a lost device, memory
  // running out) is logged, and a fresh one starts with the next scene, after a pause that grows while
  // the failures repeat. Failing before the first frame (no display, no device) is an error to report.
  auto pause = std::chrono::seconds(1);
  for (bool first = true;; first = false) {
    std::optional<Gallery> gallery;
    const SceneInfo* failing = named;
    try {
      gallery.emplace(options, named, playlist);
      return gallery->run();
    } catch (const Error& e) {
      if (first && !gallery) throw;
      if (gallery) failing = &gallery->showing();
      std::fprintf(stderr, "vitrine: kiosk: %s\nvitrine: kiosk: restarting in %lld s\n", e.what(),
                   (long long)pause.count());
    }
    gallery.reset();
    for (auto slept = std::chrono::seconds(0); slept < pause && !stopRequested; slept += std::chrono::seconds(1))
      std::this_thread::sleep_for(std::chrono::seconds(1));
    if (stopRequested) return 0;
    pause = std::min(pause * 2, std::chrono::seconds(60));
    const auto scenes = sceneRegistry();
    named = failing ? &scenes[(size_t(failing - scenes.data()) + 1) % scenes.size()] : nullptr;
  }
}

}  // namespace vitrine::host
