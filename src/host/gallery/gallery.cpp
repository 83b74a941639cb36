// The gallery's start, its frame loop and the simulation's steps (gallery_app.h says where the rest is).
#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <thread>

#include "core/stop_signal.h"
#include "core/user_dirs.h"
#include "gpu/check.h"
#include "host/filters/filter_options.h"
#include "host/gallery/gallery_app.h"
#include "host/present/output_warp_file.h"
#include "host/present/stream_sink.h"
#include "rig/pipewire_source.h"
#include "scenes/adaptive_quality.h"
#include "scenes/pieces/piece_catalogue.h"

namespace vitrine::host {
namespace {

using Clock = Gallery::Clock;
constexpr uint32_t kFramesInFlight = Gallery::kFramesInFlight;

constexpr auto kShaderPollInterval = std::chrono::milliseconds(500);
constexpr auto kNoteSeconds = std::chrono::seconds(6);  // how long a screenshot's note stays
constexpr auto kReloadNoteSeconds = std::chrono::seconds(3);
// The scene renderer's present (compute) or blit (transfer) is the first use of an acquired image,
// so that is where the acquire is waited for.
constexpr VkPipelineStageFlags2 kAcquireStage =
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
constexpr gpu::ImageUse kAcquired{kAcquireStage, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};

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

}  // namespace

const SceneInfo& Gallery::namedScene(const std::string& name) {
  if (const SceneInfo* info = findScene(name)) return *info;
  throw Error(unknownScene(name));
}

Gallery::Gallery(const Options& options, const SceneInfo* named, std::vector<PlaylistEntry> playlist)
    : window_(options.size.value_or(VkExtent2D{1280, 720}), options.fullscreen, options.monitor, options.span),
      instance_({options.validation, window_.vulkanExtensions()}),
      surface_(window_.createSurface(instance_.handle())),
      device_(instance_, {options.device, surface_.handle()}),
      programs_(checkWindowSize(device_, options.size), VITRINE_SHADER_SOURCE_DIR, /*preferNewerSources=*/true),
      settings_(params::defaultSettingsPath(), options.resetSettings, /*keepScene=*/options.kiosk),
      guard_(device_, programs_),
      flashGuard_(flashGuardOn(options)),
      renderer_(makeRenderer()),
      swapchain_(device_, surface_.handle(), window_.handle(), window_.framebufferSize(), options.vsync),
      overlay_(device_, window_.handle(), swapchain_.format(), kFramesInFlight,
               {assets_.font("Fraunces"), assets_.font("CormorantSC")},
               // The menu's place, folds and sections, beside the settings file (not in a kiosk).
               options.kiosk || settings_.path().empty() ? std::filesystem::path()
                                                         : settings_.path().parent_path() / "gallery-menu.ini",
               options.resetSettings),
      screenshots_(device_, kFramesInFlight, vitrineUserDir(UserDir::Pictures)),
      capture_(device_, kFramesInFlight, vitrineUserDir(UserDir::Videos)),
      outputs_(settings_,
               [this](VkExtent2D extent, const maths::OutputWarp& warp, std::string_view where) {
                 checkWarpedFrame(device_, extent, warp, where);
               },
               options.outputWarp,
               options.outputWarp.empty() ? std::nullopt : std::optional(readOutputWarp(options.outputWarp)),
               window_.framebufferSize()),
      steps_(input_.dt),
      vsync_(options.vsync),
      waitForBar_(options.linkWaitBar),
      remote_(options.remoteSaves) {
  overlay_.attach(swapchain_);
  keepInIni(menuLayout_);
  tiers_.setStartingTier(AdaptiveQuality::name(AdaptiveQuality::startingTier(device_)));
  if (options.remote) remote_.listen(options.remoteBind, options.remoteAllow, &presets_);
  if (options.kiosk) {
    uiHidden_ = true;
    window_.setCursorHidden(true);
  }
  for (uint32_t i = 0; i < kFramesInFlight; ++i) slots_.emplace_back(device_, i);
  if (!options.outputs.empty())
    outputs_.openWindows(instance_, device_, window_, options.outputs, vsync_, kFramesInFlight);
  if (!options.pipewire.empty()) {  // the whole frame, whatever the main window's warp
    const VkExtent2D size = options.pipewireSize.value_or(window_.framebufferSize());
    gpu::checkImageSize(device_, size);
    outputs_.add(rig::makePipeWireOutput(device_, options.pipewire, options.pipewire, maths::OutputWarp{}, size),
                 /*warpGiven=*/true, "--pipewire");
  }
  if (!options.stream.empty())  // the whole frame, at the main window's starting size
    outputs_.add(makeStreamOutput(device_, options, window_.framebufferSize(), audio_), /*warpGiven=*/true, "--stream");
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
  const SceneInfo& firstScene = !playlist.empty() ? namedScene(playlist.front().scene)
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
  // --lights, else the settings file's patch.
  if (const std::string patch = options.lights.empty() ? settings_.lightsPatch() : options.lights; !patch.empty()) {
    lights_ = std::make_unique<GalleryLights>(device_, patch, [this] {
      lights::Signals signals;
      if (hasScene_) renderer_->scene().lightSignals(signals);
      return signals;
    });
    live_->link().setDmxInput(&lights_->lights());
  }
  if (options.kiosk) {
    if (chasedByTimecode(playlist)) {
      std::vector<rig::Timecode> starts;
      for (const PlaylistEntry& entry : playlist) starts.push_back(*entry.at);
      chase_.emplace(std::move(starts));
    }
    kiosk_.emplace(std::move(playlist), firstScene, options.dwell);
    kiosk_->rest(window_.takePointer());  // where the cursor rests is not a touch
  }
  // A --filter or --transition that cannot load ends the run here, before its first frame.
  filtersGiven_ = !options.filters.empty();
  runFilters_ = filterSpecs(options);
  for (const FilterSpec& filter : runFilters_) renderer_->filters().add(filter);
  transitionGiven_ = !options.transition.empty();
  if (transitionGiven_) {
    transition_ = std::make_unique<IsfTransition>(device_, programs_, options.transition);
    if (auto why = transition_->applyParameters(options.transitionParameters); !why.empty())
      throw Error(fmt::format("transition {} rejects {}", options.transition, why));
    crossfade_.setTransition(transition_.get());
  } else if (const auto& saved = settings_.transition(); saved.is_object() && saved.contains("file")) {
    // The settings' transition: one that no longer loads is said, and the cross-fade's mix stands in.
    std::vector<std::string> problems;
    const std::vector<FilterSpec> spec = chainFromJson(nlohmann::ordered_json::array({saved}), problems);
    if (!spec.empty()) chooseTransition(spec.front().file, spec.front().values);
  }
  if (!options.kiosk) findFilters();
  switchScene(firstScene);
}

int Gallery::run() {
  while (!window_.shouldClose() && !StopOnSignal::requested()) {
    window_.pollEvents();
    if (window_.hidden()) {
      audio_.pause();  // minimised: no drone playing to nobody
      const auto hiddenAt = Clock::now();
      // Sleep on events (a few wake-ups a second, so a stop signal is still seen) until shown again.
      while (window_.hidden() && !window_.shouldClose() && !StopOnSignal::requested()) window_.waitForEvents(0.25);
      audio_.resume();
      lastFrame_ = Clock::now();  // time spent minimised is not simulated, nor counted as shown
      shownTime_.hidden(hiddenAt, lastFrame_);
      continue;
    }
    frame();
  }
  // What the scene holds now is what the settings file keeps, whatever changed it last.
  if (hasScene_ && remembers()) rememberValues();
  device_.waitIdle();
  // What the viewer saw: frames a second from the first one shown to the last.
  if (frameCount_ > 1) {
    const double seconds = shownTime_.seconds(Clock::now());
    std::fprintf(stderr, "vitrine: showed %llu frames in %.1f s (%.1f fps)\n", (unsigned long long)(frameCount_ - 1),
                 seconds, double(frameCount_ - 1) / std::max(seconds, 1e-9));
  }
  // How the published outputs fared: what they handed over and what they dropped rather than wait.
  for (const Output::Health& health : outputs_.health())
    if (health.kind != "window")
      std::fprintf(stderr, "vitrine: %s: %s; %llu frames handed over, %llu dropped\n", health.kind.c_str(),
                   health.line.c_str(), (unsigned long long)health.frames, (unsigned long long)health.dropped);
  if (lights_) std::fprintf(stderr, "vitrine: %s\n", lights_->lights().status().c_str());
  for (uint32_t slot = 0; slot < kFramesInFlight; ++slot)
    if (auto note = screenshots_.collect(slot)) std::printf("vitrine: %s\n", note->c_str());
  if (auto finished = capture_.takeFinished()) std::printf("vitrine: %s\n", finished->c_str());
  if (instance_.validationMessages() > 0) {
    std::fprintf(stderr, "%d validation messages: failing.\n", instance_.validationMessages());
    return 3;
  }
  return 0;
}

void Gallery::frame() {
  onBar_ = barLine();
  if (nextScene_ && onBar_) {
    if (!barNote_.empty())
      std::fprintf(stderr, "vitrine: link: %s: %s\n", barNote_.c_str(), std::string(nextScene_->name).c_str());
    const SceneInfo& next = *std::exchange(nextScene_, nullptr);
    if (transition_ && !kiosk_) fadeTo(next);  // the gallery's switch through the transition too
    else switchScene(next);
  }
  remote_.setBar(barWaits(), onBar_);
  if (barPreset_ && onBar_) {
    std::fprintf(stderr, "vitrine: link: %s: preset %s\n", barNote_.c_str(), barPreset_->preset.c_str());
    applyEdit(*std::exchange(barPreset_, std::nullopt));
  }
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
  rig_ = rigLines();
  remote_.setRig(rig_);
  simulate();
  showMenu();
  showToast();
  outputs_.drawSetup(swapchain_.extent());
  handleKeys();
  VkCommandBuffer cmd = current.begin();
  const bool compute = swapchain_.computeWrites();
  // Kiosk mode's cross-fade: both scenes run and draw.
  const Crossfade fade = crossfade_.record(cmd, slot, frameExtent(swapchain_.extent(), outputs_.shownWarp()));
  renderer_->setFlashGuard(flashGuard_ ? &guard_ : nullptr);
  renderer_->record(cmd, slot, shown_,
                    BlitDestination{swapchain_.image(*image), swapchain_.extent(), kAcquired, gpu::use::ColorAttachment,
                                    compute ? swapchain_.view(*image) : VK_NULL_HANDLE, compute, outputs_.shownWarp()},
                    fade);
  if (screenshots_.requested() || capture_.active()) {
    recordWindowCopy(cmd);
    const VkExtent2D rendered = renderer_->target().extent2d();
    screenshots_.record(cmd, slot, *windowCopy_, rendered, renderer_->info().name, &renderer_->timer());
    capture_.record(cmd, slot, *windowCopy_, rendered, &renderer_->timer());
  }
  // The other outputs show the same frame, each through its own warp.
  const auto outputsDrawn = outputs_.record(cmd, slot, *renderer_, fade, vsync_, kAcquireStage, shown_);
  if (lights_) lights_->record(cmd, slot, *renderer_, fade, kAcquireStage, shown_);
  slotSerial_[slot] = sceneSerial_;
  overlay_.record(cmd, *image, &renderer_->timer());
  current.submit(kAcquireStage, swapchain_.renderFinished(*image), outputsDrawn);
  cpuMs_ = secondsBetween(start, Clock::now()) * 1e3;
  swapchain_.present(*image);
  outputs_.present();
  if (lights_) lights_->present();
  // One line once the window shows its first frame: what is showing where (and what the gallery's
  // checks wait for instead of guessing how long a start takes).
  if (frameCount_++ == 0) {
    shownTime_.firstShown(Clock::now());
    std::fprintf(stderr, "vitrine: showing %s on %s\n", std::string(renderer_->info().name).c_str(),
                 device_.properties().deviceName);
  }
  // And one when projector setup first shows for an output, its card built: the calibration card
  // can take seconds to build on a busy CPU, and a corner dragged before then would be lost.
  if (const auto output = outputs_.setupNewlyShown(/*ready=*/!nextScene_))
    std::fprintf(stderr, "vitrine: projector setup of %s\n", std::string(*output).c_str());
  pollShaders();
}

// What the GPU has finished for this slot: its pass timings, and a screenshot taken in it.
void Gallery::collect(uint32_t slot) {
  // A slot last drawn by the scene before a switch or restart has that scene's timings: skipped.
  if (slotSerial_[slot] == sceneSerial_) {
    passes_ = renderer_->timer().collect(slot);
    if (!passes_.empty()) ++timedFrames_;
  }
  gpuMs_ = 0.0;
  for (const auto& pass : passes_) gpuMs_ += pass.ms;
  input_.lastGpuMs = gpuMs_;
  capture_.collect(slot);
  if (auto finished = capture_.takeFinished()) {
    std::printf("vitrine: %s\n", finished->c_str());
    std::fflush(stdout);  // said now, also when the console is a log file
  }
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
  bool touched = kiosk_ && kiosk_->touched(pointer, !keys_.empty() || !drops_.empty());
  if (remote_.on()) {
    // Values sent while this scene was hidden wait until its own frames are timed: the guard judges
    // them by what a frame of this scene costs, not by the time of the scene shown before.
    const RemoteApplied applied = remote_.apply(*renderer_, input_.time, frameMs(),
                                                timedFrames_ >= kTimedFramesBeforeWaiting ? std::optional(gpuMs_) : std::nullopt);
    touched = touched || applied.touched;
    for (const std::string& preset : applied.presetsOnBar)
      std::fprintf(stderr, "vitrine: link: %s: preset %s\n", barNote_.c_str(), preset.c_str());
    if (applied.scene) nextScene_ = applied.scene;  // from the next frame, like a number key
    if (!applied.values.empty()) rememberValues();  // saved like the panel's, playlist or not (--remote-saves)
    for (const auto& [source, value] : applied.sources) live_->link().sources().set(source, value);
    if (auto phone = remote_.pointer(window_.framebufferSize())) pointer = *phone;  // a phone drives the cursor
    remote_.publish(*renderer_);
  }
  if (kiosk_) kioskStep(elapsed, touched);
  else switchFadeStep(elapsed);
  outputs_.setupPointer(pointer);
  cursor_.observe(pointer, outputs_.setupActive() || (!uiHidden_ && overlay_.wantsMouse()));  // setup's mouse is not the scene's
  // Every step that is due, unless a step costs more than the time it stands for (StepCost).
  const int due = time_.due(steps_, elapsed, stepCost_.affordable(elapsed), renderer_->scene().takeGivenUpSeconds());
  const bool firstSteps = input_.frame == 0;  // a scene's first update builds things: not its cost
  const auto simulating = Clock::now();
  for (int left = due; left > 0; --left) {
    input_.cursor = cursor_.take();
    input_.keysPressed = std::exchange(keys_, {});
    input_.keysHeld = overlay_.wantsText() ? std::vector<int>{} : window_.keysHeld();
    input_.droppedFiles = std::exchange(drops_, {});
    input_.actions = remote_.takeActions();
    live_->step(*renderer_, input_);
    renderer_->scene().update(input_);
    // A frame's GPU time is news to its first step only: the automatic tiers count frames, and a
    // slow frame followed by many steps must not count as many slow frames.
    input_.lastGpuMs = 0.0;
    shown_ = input_;
    input_.time += input_.dt;
    ++input_.frame;
    crossfade_.step();  // the scene fading in runs on its own clock, untouched
  }
  if (!firstSteps) stepCost_.measured(due, secondsBetween(simulating, Clock::now()));
}

// Renderers of the scene showing and of one fading in: their sound, their events and real time.
std::unique_ptr<SceneRenderer> Gallery::makeRenderer() {
  auto renderer = std::make_unique<SceneRenderer>(device_, programs_, assets_, kFramesInFlight);
  renderer->setEventSink(&tiers_);
  renderer->setAudioSink(&audio_);
  renderer->setRealtime(true);
  return renderer;
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

int runGallery(const Options& options) {
  const SceneInfo* named = options.scene.empty() ? nullptr : &Gallery::namedScene(options.scene);  // a typo fails first
  // SIGTERM (a kiosk's service manager) and Ctrl-C end the loop like Esc: settings are flushed, the
  // device is idled and destroyed in order.
  const StopOnSignal stop;
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
  // the failures repeat (KioskRestartPause). Failing before the first frame (no display, no device)
  // is an error to report.
  KioskRestartPause pauses;
  for (bool first = true;; first = false) {
    std::optional<Gallery> gallery;
    const SceneInfo* failing = named;
    const auto started = std::chrono::steady_clock::now();
    std::chrono::seconds pause{0};
    try {
      gallery.emplace(options, named, playlist);
      return gallery->run();
    } catch (const Error& e) {
      if (first && !gallery) throw;
      if (gallery) failing = &gallery->showing();
      // A piece showing when the device was lost is not started again until its file is saved.
      if (pieces::Piece* piece = failing && !failing->builtIn() ? pieces::findPiece(failing->name) : nullptr)
        pieces::blame(*piece, e.what());
      pause = pauses.after(std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - started));
      std::fprintf(stderr, "vitrine: kiosk: %s\nvitrine: kiosk: restarting in %lld s\n", e.what(),
                   (long long)pause.count());
    }
    gallery.reset();
    for (auto slept = std::chrono::seconds(0); slept < pause && !StopOnSignal::requested(); slept += std::chrono::seconds(1))
      std::this_thread::sleep_for(std::chrono::seconds(1));
    if (StopOnSignal::requested()) return 0;
    const auto scenes = sceneRegistry();
    named = failing ? &scenes[(size_t(failing - scenes.data()) + 1) % scenes.size()] : nullptr;
  }
}

}  // namespace vitrine::host
