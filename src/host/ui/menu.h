#pragma once
#include "host/gallery/fixed_step.h"
// The gallery's menu: scenes, timings, vsync, the current scene's own panel, and what went wrong.
// It only draws and reports what was chosen; the frame loop decides what a choice changes.
#include "gpu/pass_timer.h"
#include "host/ui/live_panel.h"
#include "host/ui/param_panel.h"
#include "rig/rig_report.h"
#include "scenes/scene.h"

#include <functional>
#include <optional>
#include <span>
#include <utility>
#include <string>
#include <string_view>

struct ImFont;

namespace vitrine::host {

// Which of the menu's sections are open, and how many timing rows it keeps: kept in the overlay's
// layout file (with the window's place and folded state), so the menu comes back as it was left.
struct MenuLayout {
  bool time = false, panel = false, live = false, timings = false, rig = true;  // a first start shows the scene list only
  int passRows = 0;  // rows reserved in the timings table: the most passes any scene has shown
  std::string text() const;            // "time=0\npanel=1\n...": the lines of its ini section
  void readLine(std::string_view line);  // one of those lines; anything else is ignored
};

// The menu's width: narrow enough to leave the scene the window (a quarter of 1280 pixels at the
// default font), wide enough for a slider, its label and its reset button.
float menuWidth(float fontSize);

// Ableton Link's controls in the rig section, while the gallery runs with --link: whether it is in the
// session, the session's tempo and its transport. What the menu changes, the gallery leads.
struct LinkControls {
  bool joined = true;
  double tempo = 120.0;
  bool playing = false;
  bool operator==(const LinkControls&) const = default;
};

struct MenuState {
  const SceneInfo& current;
  Scene& scene;
  double fps = 0.0;
  double cpuMs = 0.0;
  std::span<const gpu::PassTime> passes;  // the last finished frame's
  bool vsync = true;
  std::string_view shaderError;  // the hot-reload compile log; empty when all shaders compile
  std::string_view note;         // where the last screenshot went, a key with no scene
  std::span<const std::string> missingAssets;  // what set-up could not fetch, and what stands in
  ImFont* titleFont = nullptr;                 // for scene names; null: the body font
  ParamPanel* panel = nullptr;                 // the scene's parameters, from its schema
  std::string_view panelError;                 // why the last edit was refused
  TimeControl time;                            // pause, single steps, speed
  bool help = false;                           // the help card is showing (F1 or ?)
  std::string capture;                         // the live capture's status (F9); empty before the first
  bool capturing = false;
  std::string_view reloaded;                   // "reloaded kifs/march.comp", for a few seconds after
  std::string remote;                          // remote play's status; empty without --remote
  std::string costly;                          // an edit that would freeze the window: what it costs
  std::string tierInUse;                       // "auto: low": the quality tier the scene runs at
  std::string clock;                           // "simulation behind the clock: ...", when it is
  MenuLayout* layout = nullptr;                // open sections and reserved rows, kept across runs
  LivePanel* livePanel = nullptr;              // live input: audio, MIDI, gamepads, mappings
  LivePanelState live;
  bool flashGuard = false;                     // frames go through the flash guard
  UserPresets userPresets;                     // the user's presets of the scene, for the panel's list
  std::span<const rig::RigLine> rig;           // the clocks followed and the outputs published; none: no section
  std::optional<LinkControls> link;            // with --link
  std::function<void()> filters;               // draws the filters section (its choices kept by the caller)
};

struct MenuChoice {
  const SceneInfo* scene = nullptr;  // a scene to start afresh (the current one restarts)
  bool vsync = true;
  std::optional<PanelEdit> edit;     // what the user changed in the parameter panel
  TimeControl time;                  // as the menu's controls left it
  bool help = false;
  bool capture = false;              // live capture on (F9)
  std::optional<bool> costly;        // the answer about the costly edit: apply (true) or not
  LivePanelChoice live;              // what the user asked of live input
  bool flashGuard = false;           // the flash guard's switch as the menu left it
  std::optional<LinkControls> link;  // as the menu left them, when the user changed one
};

MenuChoice drawMenu(const MenuState& state);
// Registers `layout` with the current Dear ImGui context's ini file ([Vitrine][menu]); it must outlive
// the context, which writes it when it is destroyed.
void keepInIni(MenuLayout& layout);
// A small note in the bottom-left corner, over everything, without a window frame (the UI hidden).
void drawToast(std::string_view text);
// The menu has the keyboard: a field is being typed into, or a widget (a slider turned into a field by
// Ctrl+click, one this very frame's click activated) is active. Gallery keys then do nothing.
bool menuHasKeyboard();

// The gallery's own keys, as the help card lists them: key, what it does.
std::span<const std::pair<std::string_view, std::string_view>> galleryKeys();
// "1-5": the number keys the registered scenes have.
std::string sceneKeyRange();


}  // namespace vitrine::host
