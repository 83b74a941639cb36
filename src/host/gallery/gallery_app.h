#pragma once
// The windowed gallery: the frame loop tying the window, swapchain, scene renderer, overlay and
// screenshots together. Two frames are in flight: the CPU records one while the GPU runs the other.
// Its parts live in three files: gallery.cpp (start, the frame loop, the simulation's steps),
// gallery_scenes.cpp (switching scenes, driving the kiosk's timetable and cross-fade) and gallery_menu.cpp
// (keys, the menu, parameter edits and presets, screenshots and captures, starting projector setup).
// Its rooms are objects of their own: the kiosk (KioskTimetable, KioskCrossfade), the remote session
// (RemoteSession) and the outputs with projector setup (GalleryOutputs). runGallery (host/modes.h) is
// the way in.
#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "audio/engine.h"
#include "core/assets.h"
#include "host/cost_guard.h"
#include "host/cursor_tracker.h"
#include "host/gallery/fixed_step.h"
#include "host/gallery/frame_slot.h"
#include "host/gallery/gallery_lights.h"
#include "host/gallery/gallery_live.h"
#include "host/gallery/gallery_settings.h"
#include "host/gallery/kiosk_crossfade.h"
#include "host/gallery/kiosk_timetable.h"
#include "host/gallery/timecode_chase.h"
#include "host/gallery/live_capture.h"
#include "host/ui/menu.h"
#include "host/modes.h"
#include "host/gallery/gallery_outputs.h"
#include "host/ui/overlay.h"
#include "host/ui/filter_panel.h"
#include "host/ui/param_panel.h"
#include "host/gallery/remote_session.h"
#include "host/scene_renderer.h"
#include "host/gallery/screenshot.h"
#include "host/gallery/shown_time.h"
#include "host/present/swapchain.h"
#include "host/gallery/tier_watch.h"
#include "host/user_presets.h"
#include "host/present/window.h"

namespace vitrine::host {

class Gallery {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr uint32_t kFramesInFlight = 2;
  // The scene `name` names; throws vitrine::Error naming the scenes there are.
  static const SceneInfo& namedScene(const std::string& name);

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
  void switchScene(const SceneInfo& info);
  void simulate();
  void collect(uint32_t slot);
  void showMenu();
  void showToast();
  std::string clockNote() const;
  std::vector<rig::RigLine> rigLines() const;  // the clocks followed and the outputs published, now
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
  // Once a frame: whether a scene switch may happen now. With --link-wait-bar only on the first frame of
  // a bar of the Link session; else always.
  bool barLine();
  bool barWaits() { return waitForBar_ && live_->link().linkClock(); }  // switches and presets wait for bars
  void chaseStep(double elapsed);
  void startEntryPreset(SceneRenderer& renderer, size_t entry);
  void finishFade();
  void nowShowing();
  std::unique_ptr<SceneRenderer> makeRenderer();
  // ISF filters and transitions (gallery_filters.cpp).
  void startFilters(SceneRenderer& renderer, const SceneInfo& info);
  void rememberFilters();
  void fadeTo(const SceneInfo& info);
  void switchFadeStep(double elapsed);
  void drawFilters();
  void applyFilterChoice(const FilterPanelChoice& choice);
  void findFilters();
  void chooseTransition(const std::optional<std::filesystem::path>& file, const params::KeyValues& values);
  void rememberTransition();
  // A kiosk's playlist presets are not remembered, so that a line without a preset shows the scene as
  // saved, whatever an earlier line set.
  bool remembers() const { return !kiosk_ || !kiosk_->playlist(); }

  Assets assets_ = Assets::locate();
  std::vector<std::string> missingAssets_ = assets_.missing();
  Window window_;
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
  KioskCrossfade crossfade_{[this] { return makeRenderer(); }};  // kiosk mode: the scene fading in
  // After the renderers, so it goes first: they drain the device of what it retires.
  std::unique_ptr<IsfTransition> transition_;  // --transition: drawn instead of the cross-fade's mix
  std::vector<FilterSpec> runFilters_;         // --filter, with its --set values: every scene's chain
  bool filtersGiven_ = false;                  // --filter given: the saved chains are not used or written
  std::optional<double> switchFade_;           // seconds into a scene switch's transition (not the kiosk's)
  FilterPanel filterPanel_;                    // the menu's filters section
  FilterPanelChoice filterChoice_;             // what it reported this frame
  std::string filterError_;                    // why the last filter edit or addition was refused
  std::vector<std::filesystem::path> availableFilters_;  // the filters in the pieces folder
  std::vector<std::filesystem::path> availableTransitions_;  // and the transitions
  bool transitionGiven_ = false;               // --transition: the settings' transition is not used or written
  // Per scene, the saved filters that did not load (a file gone, an edit that does not compile): kept
  // in its saved chain, after the ones that run, so that a file mended or put back runs again.
  std::map<std::string, std::vector<FilterSpec>, std::less<>> unloadedFilters_;
  Swapchain swapchain_;
  Overlay overlay_;
  Screenshots screenshots_;
  LiveCapture capture_;
  std::vector<FrameSlot> slots_;
  GalleryOutputs outputs_;  // the main window's warp, --outputs' windows and projector setup (F7)
  uint64_t frameCount_ = 0;
  uint64_t sceneSerial_ = 0;           // counts scene switches and restarts
  std::vector<uint64_t> slotSerial_ = std::vector<uint64_t>(kFramesInFlight);  // the scene each slot drew

  FrameInput input_;  // the next simulation step's
  FrameInput shown_;  // the last step's: what the frame being recorded shows
  FixedStep steps_;   // after input_, whose dt it is built from
  StepCost stepCost_;  // what a step of the scene showing costs: how many fit in a frame
  TimeControl time_;  // pause, single steps, speed
  // The scene's picture at the window's size, scaled as the present pass scales it but without an
  // output's warp, the flash guard's hold-back or a cross-fade: what F12 and F9 save.
  std::optional<gpu::Image> windowCopy_;
  bool helpShown_ = false;
  const SceneInfo* beforeSetup_ = nullptr;  // the scene projector setup switched away from (to the card)
  CursorTracker cursor_{/*waitForMovement=*/true};
  std::vector<int> keys_;  // pressed since the last step
  std::vector<std::string> drops_;  // files dropped since the last step

  bool vsync_;
  bool uiHidden_ = false;
  bool hasScene_ = false;
  const SceneInfo* nextScene_ = nullptr;
  bool waitForBar_ = false;  // --link-wait-bar
  rig::BarGate barGate_;
  bool onBar_ = true;        // this frame may switch scenes (barLine())
  std::string barNote_;      // the bar that began this frame, for the console
  std::optional<PanelEdit> barPreset_;  // a preset chosen in the panel, waiting for the next bar
  Clock::time_point lastFrame_ = Clock::now();
  ShownTime shownTime_;  // from the first frame presented, minimised spells left out: the run's frame rate
  Clock::time_point lastShaderPoll_ = Clock::now();
  double frameSeconds_ = 0.0;  // smoothed over about twenty frames, for the fps readout
  double cpuMs_ = 0.0;
  double gpuMs_ = 0.0;  // the last finished frame's, all passes
  std::vector<gpu::PassTime> passes_;
  uint32_t timedFrames_ = 0;  // frames of the scene showing whose GPU time has come back
  // A scene's first frames build things (strands, lattices): the values sent while it was hidden are
  // judged after these many of its frames are timed.
  static constexpr uint32_t kTimedFramesBeforeWaiting = 4;
  std::string reloadNote_;  // which shaders were reloaded, shown for kReloadNoteSeconds
  Clock::time_point reloadNoted_{};
  std::string note_;  // where the last screenshot went, a key with no scene: shown for kNoteSeconds
  Clock::time_point noted_{};
  ParamPanel panel_;
  std::string panelError_;  // why the last edit was refused
  std::optional<PanelEdit> costlyEdit_;  // an edit that would freeze the window, waiting for a yes
  std::string costlyWhy_;

  std::optional<KioskTimetable> kiosk_;  // --kiosk (and --playlist): what shows when
  std::optional<TimecodeChase> chase_;   // a playlist chased by timecode: which line the show is on
  std::string chaseSaid_;                // the chase's state as last said on the console
  RemoteSession remote_;  // --remote: the clients, and the values they set
  std::vector<rig::RigLine> rig_;  // this frame's rigLines(), for the menu and the remote page
  std::unique_ptr<GalleryLights> lights_;  // --lights: DMX out, and in for live_ (which goes first)
  std::unique_ptr<GalleryLive> live_;  // audio, MIDI, gamepads and OSC through the mappings
};

}  // namespace vitrine::host
